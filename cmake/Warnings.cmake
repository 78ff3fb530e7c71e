# SPDX-License-Identifier: GPL-3.0-or-later
# Warnings as an INTERFACE target, linked PRIVATE by every project target.
add_library(fivebar_warnings INTERFACE)
add_library(fivebar::warnings ALIAS fivebar_warnings)
target_compile_options(fivebar_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow=local -Wnon-virtual-dtor>)
