# The web build's native half (docs/web.md): oasis-serve, the page server, and the tests of label
# `web`, registered only where the web build exists (build-web/oasis.html, made by
# `bash .ci/setup-web`) or OASIS_WEB_TESTS is on; the web build itself is src/web/CMakeLists.txt.
# Its HTTP is cpp-httplib's (Debian's libcpp-httplib-dev: a compiled library with a pkg-config file);
# it shares only io/printable_text.cpp with oasis (the escaping of what it logs).
pkg_check_modules(HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)
add_executable(oasis-serve ${CMAKE_CURRENT_SOURCE_DIR}/src/serve/serve_main.cpp
               ${CMAKE_CURRENT_SOURCE_DIR}/src/io/printable_text.cpp)
target_include_directories(oasis-serve PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
target_compile_options(oasis-serve PRIVATE -Wall -Wextra)
target_link_libraries(oasis-serve PRIVATE PkgConfig::HTTPLIB Threads::Threads)
set_target_properties(oasis-serve PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR})

set(OASIS_WEB_DIR ${CMAKE_CURRENT_SOURCE_DIR}/build-web CACHE PATH "the web build's output (bash .ci/setup-web)")
option(OASIS_WEB_TESTS "Register the browser tests (label web) even before build-web/oasis.html exists" OFF)
if(OASIS_WEB_TESTS OR EXISTS ${OASIS_WEB_DIR}/oasis.html)
  # Headless Chromium on SwiftShader: WebGL 2, both pipelines against native --api gles --force gles30.
  add_test(NAME web.page_draws_and_matches_native
           COMMAND node --experimental-websocket --no-warnings ${CMAKE_CURRENT_SOURCE_DIR}/tests/web/web_test.mjs
                   ${CMAKE_BINARY_DIR} ${OASIS_WEB_DIR} ${CMAKE_BINARY_DIR}/web-out 320x180)
  add_test(NAME web.size_under_3mb_gzipped COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/tests/web/size.sh ${OASIS_WEB_DIR})
  set_tests_properties(web.page_draws_and_matches_native web.size_under_3mb_gzipped PROPERTIES LABELS web TIMEOUT 660)
endif()
