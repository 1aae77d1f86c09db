# libFuzzer targets: one executable per input reader (the scene and mesh readers, texture images,
# the resume journal), fuzz/<reader>_fuzz.cpp, built with clang's -fsanitize=fuzzer. The loaders
# (rayo_scene) get coverage instrumentation so libFuzzer can steer; the rest of core and shading
# does not, which keeps the sanitizer test run that shares this build fast.
# Each fuzzer is a ctest entry `fuzz_<reader>` that runs for RAYO_FUZZ_SECONDS over a copy of its
# seed corpus fuzz/corpus/<reader>/ (cmake/run_fuzzer.cmake); fuzz/run.sh runs them longer.
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "RAYO_FUZZ needs clang (libFuzzer): configure with the asan preset or "
                      "-DCMAKE_CXX_COMPILER=clang++")
endif()

set(RAYO_FUZZ_SECONDS 20 CACHE STRING "Seconds each fuzzer runs as a ctest entry")

target_compile_options(rayo_scene PRIVATE -fsanitize=fuzzer-no-link)
# The input readers that live below the scene layer get it too, file by file: the resume journal
# (journal_fuzz) and the texture checks before an image is registered (texture_fuzz).
set_source_files_properties(core/image/partial_render.cpp shading/image_texture.cpp
                            PROPERTIES COMPILE_OPTIONS -fsanitize=fuzzer-no-link)

# Readers whose ctest entry only replays the seed corpus (each seed once, -runs=0) instead of
# mutating for RAYO_FUZZ_SECONDS, for a reader that still fails on fresh inputs within a minute
# (which would make CI fail at random); fuzz/run.sh fuzzes them as the others. None now: mesh was
# one while assimp read PLY, STL and OFF (docs/limits.md, "Fuzzing"); rayo's own readers ran
# 5 million inputs in 10 minutes without a finding.
set(RAYO_FUZZ_REPLAY_ONLY "")

file(GLOB RAYO_FUZZ_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/*_fuzz.cpp)
foreach(src ${RAYO_FUZZ_SOURCES})
  get_filename_component(name ${src} NAME_WE)  # e.g. nff_fuzz
  string(REGEX REPLACE "_fuzz$" "" reader ${name})
  add_executable(${name} ${src})
  target_compile_options(${name} PRIVATE -fsanitize=fuzzer)
  target_link_options(${name} PRIVATE -fsanitize=fuzzer)
  target_link_libraries(${name} PRIVATE rayo_scene rayo_image)
  add_dependencies(${name} rayo_oiio)
  set(dict ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/${reader}.dict)
  if(NOT EXISTS ${dict})
    set(dict "")
  endif()
  set(replay 0)
  if(reader IN_LIST RAYO_FUZZ_REPLAY_ONLY)
    set(replay 1)
  endif()
  add_test(NAME fuzz_${reader}
           COMMAND ${CMAKE_COMMAND}
                   -DFUZZER=$<TARGET_FILE:${name}>
                   -DCORPUS=${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/${reader}
                   -DWORK=${CMAKE_CURRENT_BINARY_DIR}/fuzz/${reader}
                   -DSECONDS=${RAYO_FUZZ_SECONDS}
                   -DDICT=${dict}
                   -DREPLAY=${replay}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/cmake/run_fuzzer.cmake)
  math(EXPR timeout "${RAYO_FUZZ_SECONDS} + 120")
  set_tests_properties(fuzz_${reader} PROPERTIES TIMEOUT ${timeout} LABELS fuzz)
endforeach()
