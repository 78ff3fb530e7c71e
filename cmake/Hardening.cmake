# SPDX-License-Identifier: GPL-3.0-or-later
# The hardening flags Debian builds packages with (dpkg-buildflags; lintian's hardening-* tags),
# for the optimised builds only (_FORTIFY_SOURCE needs optimisation; the debug preset has its
# sanitizers): checked libc calls, stack protector, read-only relocations bound at start-up.
# The executables are PIE already (GCC's default on Debian). A distribution build that passes
# its own dpkg-buildflags turns this off with -DFIVEBAR_HARDENING=OFF.
option(FIVEBAR_HARDENING "Build Release binaries with the Debian hardening flags" ON)
if(FIVEBAR_HARDENING AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  set(optimised "$<CONFIG:Release,RelWithDebInfo,MinSizeRel>")
  add_compile_options("$<$<AND:${optimised},$<COMPILE_LANGUAGE:CXX>>:-D_FORTIFY_SOURCE=2;-fstack-protector-strong>")
  add_link_options("$<${optimised}:LINKER:-z,relro,-z,now>")
endif()
