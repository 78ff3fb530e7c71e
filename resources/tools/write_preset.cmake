# SPDX-License-Identifier: GPL-3.0-or-later
# cmake -DCLI=fivebar -DNAME=PRESET -DOUT=FILE.json -P write_preset.cmake: `fivebar profile show
# PRESET` into FILE.json, failing the build when the CLI fails.
execute_process(COMMAND "${CLI}" profile show "${NAME}" OUTPUT_FILE "${OUT}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  file(REMOVE "${OUT}")
  message(FATAL_ERROR "fivebar profile show ${NAME} failed (${rc})")
endif()
