# The sanitizer build's test settings (tests/CMakeLists.txt includes this under OASIS_SANITIZE);
# docs/sanitizers.md says why each one is there.
#   exitcode=23          a sanitizer report fails every test, also those that expect exit 1 or 2
#   halt_on_error=1      UBSan stops at its first report (the code is built -fno-sanitize-recover)
#   print_stacktrace=1   UBSan prints where, not only what
#   suppressions         LeakSanitizer ignores leaks inside Mesa and LLVM only (sanitize/lsan.supp)
#   LD_PRELOAD=swrast_dri.so, verify_asan_link_order=0
#                        Mesa's EGL unloads its driver (and LLVM with it) at eglTerminate; LSan cannot
#                        scan an unmapped library's globals, so what only they point to looks leaked,
#                        from "<unknown module>". Preloaded, the driver stays mapped. ASan must come
#                        first among the loaded libraries only to intercept their calls; the driver
#                        defines no allocator, so the check is off for it.
find_file(OASIS_MESA_DRIVER swrast_dri.so PATHS /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/dri /usr/lib/dri /usr/lib64/dri
          NO_DEFAULT_PATH)
set(OASIS_SANITIZER_ENVIRONMENT
  "ASAN_OPTIONS=exitcode=23:detect_leaks=1:halt_on_error=1:verify_asan_link_order=0"
  "UBSAN_OPTIONS=exitcode=23:halt_on_error=1:print_stacktrace=1"
  "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
if(OASIS_MESA_DRIVER)
  list(APPEND OASIS_SANITIZER_ENVIRONMENT "LD_PRELOAD=${OASIS_MESA_DRIVER}")
endif()

# cli tests that do not run oasis on llvmpipe (other drivers: the driver matrix's job; a grep).
set(OASIS_SANITIZE_SKIPPED_CLI_TESTS
  cli.caps_zink cli.caps_softpipe cli.softpipe_bare_gl33_tier cli.no_blits_copies_or_dsa_in_the_renderer
  # zink over lavapipe under the sanitizer's preload fails as cli.caps_zink does
  cli.zink_no_runtime_dir_error cli.probe_shading_zink cli.probe_shading_zink_ubo_refused cli.driver_compare_zink
  # the bench's interruption and the full perturbed check take minutes there (the other commands'
  # interruption cases and check --quick run sanitized); the browser test runs no oasis at all;
  # the pixel history's test renders ~150 frames (cli.probe_shading runs the probe's new paths sanitized,
  # and its perturbed twin the same paths over another shader tree)
  cli.interruption_bench cli.check_perturbed cli.check_html_in_chromium cli.probe_history
  cli.probe_shading_perturbed
  # every writer of every subcommand, about 40 renders (155 s sanitized against 19 s): the other
  # provenance cases run its code sanitized; the driver comparison's timeout case waits out a
  # 15 s limit (the other driver_compare cases run the child-process code sanitized)
  cli.provenance_writers cli.driver_compare_timeout
  # the broken driver's cases preload their own stand-in library and render in dozens of children:
  # the child-process code runs sanitized in cli.check_quick and cli.check_driver_references
  cli.check_driver_crash cli.check_driver_hang cli.check_driver_flake cli.check_driver_expectations
  cli.check_driver_farm cli.check_driver_blame
  # frame comparisons between paths, tiers and set-ups of llvmpipe: their frames come from the
  # renderer code the sanitized GPU suite draws (every path, tier and layout), and what they add
  # (comparing two images, a JSON) the kept compare, caps, probe and output tests run sanitized;
  # sanitized they cost minutes of CI's 90 (the normal tree runs them all)
  cli.compare_ratios_agree cli.compare_pass_times cli.pass_clock_llvmpipe_untrusted
  cli.render_atlas_no_compute cli.render_atlas_without_compute_context cli.compare_json_without_compute_context
  cli.compare_json_plants_on_gpu cli.compare_json_vegetation cli.compare_json_vegetation_off cli.compare_json_lights
  cli.compare_lights_without_ssbo_context cli.compare_json_light_method_tiled cli.compare_light_method_forced_no_compute
  cli.compare_light_method_without_compute_context cli.compare_light_method_tiled_on_ubo_path
  cli.compare_json_reversed_z cli.gles_without_depth_clamp cli.water_without_depth_clamp cli.gles_frames_equal_desktop
  cli.gles31_frames_equal_gles cli.gles_probe_equals_desktop cli.depth_stencil_drawn
  cli.force_gl33_draws_the_unforced_image cli.norm16_fallback_render cli.norm16_fallback_check
  cli.driver_compare_forced cli.driver_compare_native cli.driver_compare_altered
  cli.frame_graph_order cli.frame_graph_docs cli.render_validated_frames
  cli.caps_gles31 cli.caps_gles31_without_gpu_shader5 cli.caps_gles_without_norm16 cli.caps_forced_gl33_tier
  cli.caps_no_ssbo_compute
  # the output limit's bench case: the limit's code runs sanitized in its compare case, the bench's
  # writers in cli.bench_quick_smoke
  cli.output_size-limit-bench
  # checks over perturbed shader copies (the tile lists one tile on, the interior rule's and the
  # oracle's errors): the oracle, the interior split and the buffers' search run sanitized in
  # cli.check_quick's cases; the target memory's compare: the graph's plan runs in the sanitized GPU
  # suite, compare's JSON in the kept compare tests
  cli.check_tiles cli.check_oracle cli.check_interior cli.compare_target_memory)
