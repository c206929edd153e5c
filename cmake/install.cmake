# Install rules: the `arbiter` command, its man page and bash completion, the libraries'
# static archives and public headers, and the CMake package (lib/cmake/arbiter) that gives
# find_package(arbiter) the imported targets and arbiter_add_shaders() (docs/api.md).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(ARBITER_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/arbiter)

# Two export sets, so that a build pipeline can use the command without arbiter's development
# dependencies: component `tool` (arbiter::arbiter) and component `libraries`.
set_target_properties(arbiter PROPERTIES EXPORT_NAME arbiter)
install(TARGETS arbiter EXPORT arbiterToolTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

foreach(lib compiler arbvp glsl targets runtime)
  set_target_properties(arbiter_${lib} PROPERTIES EXPORT_NAME ${lib})
  install(TARGETS arbiter_${lib}
    EXPORT arbiterLibraryTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${lib}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
# glstate is header-only (an INTERFACE library): its headers and its target.
set_target_properties(arbiter_glstate PROPERTIES EXPORT_NAME glstate)
install(TARGETS arbiter_glstate EXPORT arbiterLibraryTargets
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/glstate/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# arbvp is three libraries (front end, emitter, interpreter) behind arbiter::arbvp.
foreach(part front emit exec)
  set_target_properties(arbiter_arbvp_${part} PROPERTIES EXPORT_NAME arbvp_${part})
  install(TARGETS arbiter_arbvp_${part}
    EXPORT arbiterLibraryTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
endforeach()

# Static libraries compiled with sanitizers need the sanitizer runtimes in the program that
# links them: the installed targets carry the build's -fsanitize flags to their users.
# (fuzzer-no-link only instruments: it has no runtime to link.)
string(REPLACE ",fuzzer-no-link" "" arbiter_cxx_flags "${CMAKE_CXX_FLAGS}")
string(REGEX MATCHALL "-fsanitize=[^ ]+" ARBITER_SANITIZE_FLAGS "${arbiter_cxx_flags}")
list(FILTER ARBITER_SANITIZE_FLAGS EXCLUDE REGEX "^-fsanitize=fuzzer-no-link$")
if(ARBITER_SANITIZE_FLAGS)
  target_link_options(arbiter_compiler INTERFACE $<INSTALL_INTERFACE:${ARBITER_SANITIZE_FLAGS}>)
endif()

install(EXPORT arbiterToolTargets
  NAMESPACE arbiter::
  DESTINATION ${ARBITER_INSTALL_CMAKEDIR})
install(EXPORT arbiterLibraryTargets
  NAMESPACE arbiter::
  DESTINATION ${ARBITER_INSTALL_CMAKEDIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/arbiterConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmake/arbiterConfig.cmake
  INSTALL_DESTINATION ${ARBITER_INSTALL_CMAKEDIR})
# 0.x: a minor version may change the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmake/arbiterConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES
  ${PROJECT_BINARY_DIR}/cmake/arbiterConfig.cmake
  ${PROJECT_BINARY_DIR}/cmake/arbiterConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/arbiterShaders.cmake
  DESTINATION ${ARBITER_INSTALL_CMAKEDIR})

install(FILES ${PROJECT_SOURCE_DIR}/docs/arbiter.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${PROJECT_SOURCE_DIR}/completions/arbiter.bash
  DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
  RENAME arbiter)
