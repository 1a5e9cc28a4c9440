# The sanitizer build's test settings (tests/CMakeLists.txt includes this under OASIS_SANITIZE);
# docs/sanitizers.md says why each one is there.
#   exitcode=23          a sanitizer report fails every test, also those that expect exit 1 or 2
#   halt_on_error=1      UBSan stops at its first report (the code is built -fno-sanitize-recover)
#   print_stacktrace=1   UBSan prints where, not only what
#   suppressions         LeakSanitizer ignores leaks inside Mesa and LLVM only (sanitize/lsan.supp)
set(OASIS_SANITIZER_ENVIRONMENT
  "ASAN_OPTIONS=exitcode=23:detect_leaks=1:halt_on_error=1"
  "UBSAN_OPTIONS=exitcode=23:halt_on_error=1:print_stacktrace=1"
  "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")

# The GPU suite under the sanitizers, on llvmpipe: a subset (the whole suite takes too long here).
set(OASIS_SANITIZE_GPU_FILTER "*")

# cli tests that do not run oasis on llvmpipe (other drivers: the driver matrix's job; a grep).
set(OASIS_SANITIZE_SKIPPED_CLI_TESTS
  cli.caps_zink cli.caps_softpipe cli.softpipe_bare_gl33_tier cli.no_blits_copies_or_dsa_in_the_renderer)
