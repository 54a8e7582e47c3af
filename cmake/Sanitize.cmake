# Sanitizer build: RANGESIM_SANITIZE=ON compiles and links every target with
# -fsanitize=address,undefined (g++ or clang), stopping at the first report. scripts/sanitize.sh
# makes such a build next to the normal one and runs the golden, core, cli, badinput and stress
# tests in it; a normal build with tests registers it as the ctest `sanitize` (labels sanitize,
# heavy: it rebuilds the project, see the timing in scripts/sanitize.sh).
option(RANGESIM_SANITIZE "Build with -fsanitize=address,undefined" OFF)

if(RANGESIM_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=address,undefined)
endif()

function(rangesim_sanitize_test)
  if(RANGESIM_BUILD_TESTS AND NOT RANGESIM_SANITIZE AND NOT RANGESIM_FUZZ)
    add_test(NAME sanitize COMMAND ${PROJECT_SOURCE_DIR}/scripts/sanitize.sh ${PROJECT_BINARY_DIR}/sanitize-build)
    set_tests_properties(sanitize PROPERTIES LABELS "sanitize;heavy" TIMEOUT 3600)
  endif()
endfunction()
