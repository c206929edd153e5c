# arbiter_add_shaders(): check (and translate) shaders as build steps, one step per shader;
# arbiter_add_program() (at the end): shaders checked together as one program.
#
#   arbiter_add_shaders(TARGET <target> SOURCES <files...>
#                       [TRANSLATE_TO <dir>] [TRANSLATE_TARGET <t>] [LIMITS <profile>]
#                       [WERROR])
#
# Adds the custom target <target> (built by ALL) and, for each shader, one custom command
# whose declared outputs are exactly what it writes, so that Ninja and Make re-run the steps
# of the shaders that changed and nothing else:
#   - a GLSL shader (.vert .vs .frag .fs), or any shader when TRANSLATE_TO is not given, runs
#     `arbiter check` and, only when the check passes, touches the stamp
#     ${CMAKE_CURRENT_BINARY_DIR}/arbiter/<path>.stamp (<path>: the shader's path relative to
#     CMAKE_CURRENT_SOURCE_DIR). A rejected shader fails the build and leaves no stamp.
#   - with TRANSLATE_TO, an ARB program runs `arbiter translate`, which writes
#     <dir>/<name>.vert (a `!!ARBvp1.0` program) or <dir>/<name>.frag (`!!ARBfp1.0`) and its
#     binding map <dir>/<name>.<vert|frag>.bindings.json (<name>: the file name without its
#     extension). arbiter writes both atomically and only when the program is accepted.
#     TRANSLATE_TARGET passes `--target <t>` (glsl110, the default, glsl120, glsl330, es100,
#     es300, vk450, spirv, hlsl or msl): spirv, hlsl and msl append .spv, .hlsl and .metal to
#     the shader's name (<dir>/<name>.vert.spv).
# Every step depends on its shader and on the arbiter executable (a new arbiter re-checks
# everything); LIMITS (a built-in profile: spec-min, mesa, r300, r500, i915, nv30 or nv40; or
# a JSON file, which the steps then depend on too) passes --limits, WERROR passes --Werror.
# Relative paths are relative to CMAKE_CURRENT_SOURCE_DIR.
#
# The output name of a translation depends on the program's stage, which is read from its
# header when CMake configures. Each translated ARB program is therefore a configure
# dependency: editing it re-runs CMake (quick) before the build step, so a header changed from
# !!ARBvp1.0 to !!ARBfp1.0 renames the output. The step also passes the stage it expects
# (--stage), so a stale configuration fails the build instead of writing an undeclared file.
# An ARB program without a recognisable header is only checked: the check reports the
# problem. The names of the outputs are in the target's property ARBITER_OUTPUTS.
include_guard(GLOBAL)
if(CMAKE_VERSION VERSION_LESS 3.20)
  message(FATAL_ERROR "arbiter_add_shaders needs CMake 3.20 or later (cmake_path)")
endif()

# The arguments LIMITS and WERROR give every step: `flags` (--limits, --Werror) and `depends`
# (a JSON profile, made absolute so a step can run from any directory).
function(_arbiter_common_flags limits werror flags_var depends_var)
  set(flags "")
  set(depends "")
  if(limits)
    if(NOT limits MATCHES "^(spec-min|mesa|r300|r500|i915|nv30|nv40)$")
      cmake_path(ABSOLUTE_PATH limits BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}")
      set(depends "${limits}")
    endif()
    list(APPEND flags --limits "${limits}")
  endif()
  if(werror)
    list(APPEND flags --Werror)
  endif()
  set(${flags_var} "${flags}" PARENT_SCOPE)
  set(${depends_var} "${depends}" PARENT_SCOPE)
endfunction()

function(arbiter_add_shaders)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "WERROR" "TARGET;TRANSLATE_TO;TRANSLATE_TARGET;LIMITS" "SOURCES")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "arbiter_add_shaders: unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_TARGET OR NOT ARG_SOURCES)
    message(FATAL_ERROR "arbiter_add_shaders: TARGET and SOURCES are required")
  endif()
  if(NOT TARGET arbiter::arbiter)
    message(FATAL_ERROR "arbiter_add_shaders: no arbiter::arbiter target (find_package(arbiter))")
  endif()

  _arbiter_common_flags("${ARG_LIMITS}" "${ARG_WERROR}" flags limits_depends)
  if(ARG_TRANSLATE_TO)
    set(translate_dir "${ARG_TRANSLATE_TO}")
    cmake_path(ABSOLUTE_PATH translate_dir BASE_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
  endif()

  set(outputs "")
  foreach(source IN LISTS ARG_SOURCES)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}"
               NORMALIZE OUTPUT_VARIABLE path)
    if(NOT EXISTS "${path}")
      message(FATAL_ERROR "arbiter_add_shaders: no such shader: ${source}")
    endif()
    cmake_path(RELATIVE_PATH path BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}"
               OUTPUT_VARIABLE relative)
    # A shader outside the source tree keeps its stamp inside the build tree.
    string(REPLACE "../" "__/" relative "${relative}")
    cmake_path(GET path EXTENSION LAST_ONLY extension)
    cmake_path(GET path STEM LAST_ONLY name)

    set(stage "")
    if(ARG_TRANSLATE_TO AND NOT extension MATCHES "^\\.(vert|vs|frag|fs)$")
      file(READ "${path}" header LIMIT 16)
      if(header MATCHES "^!!ARBvp1\\.0")
        set(stage arbvp)
        set(glsl_extension vert)
      elseif(header MATCHES "^!!ARBfp1\\.0")
        set(stage arbfp)
        set(glsl_extension frag)
      endif()
      set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${path}")
    endif()

    if(stage)
      set(shader "${translate_dir}/${name}.${glsl_extension}")
      set(target_flags "")
      if(ARG_TRANSLATE_TARGET)
        set(target_flags --target "${ARG_TRANSLATE_TARGET}")
        if(ARG_TRANSLATE_TARGET STREQUAL "spirv")
          string(APPEND shader ".spv")
        elseif(ARG_TRANSLATE_TARGET STREQUAL "hlsl")
          string(APPEND shader ".hlsl")
        elseif(ARG_TRANSLATE_TARGET STREQUAL "msl")
          string(APPEND shader ".metal")
        endif()
      endif()
      set(step_outputs "${shader}" "${shader}.bindings.json")
      add_custom_command(
        OUTPUT ${step_outputs}
        COMMAND "${CMAKE_COMMAND}" -E make_directory "${translate_dir}"
        COMMAND arbiter::arbiter translate --stage ${stage} ${flags} ${target_flags}
                -o "${shader}" --bindings "${shader}.bindings.json" "${path}"
        DEPENDS "${path}" "$<TARGET_FILE:arbiter::arbiter>" ${limits_depends}
        COMMENT "arbiter translate ${relative}"
        VERBATIM)
    else()
      set(stamp "${CMAKE_CURRENT_BINARY_DIR}/arbiter/${relative}.stamp")
      cmake_path(GET stamp PARENT_PATH stamp_dir)
      set(step_outputs "${stamp}")
      add_custom_command(
        OUTPUT "${stamp}"
        COMMAND "${CMAKE_COMMAND}" -E make_directory "${stamp_dir}"
        COMMAND arbiter::arbiter check ${flags} "${path}"
        COMMAND "${CMAKE_COMMAND}" -E touch "${stamp}"
        DEPENDS "${path}" "$<TARGET_FILE:arbiter::arbiter>" ${limits_depends}
        COMMENT "arbiter check ${relative}"
        VERBATIM)
    endif()
    foreach(output IN LISTS step_outputs)
      if(output IN_LIST outputs)
        message(FATAL_ERROR "arbiter_add_shaders: two shaders would write ${output}")
      endif()
    endforeach()
    list(APPEND outputs ${step_outputs})
  endforeach()

  add_custom_target(${ARG_TARGET} ALL DEPENDS ${outputs})
  set_property(TARGET ${ARG_TARGET} PROPERTY ARBITER_OUTPUTS ${outputs})
endfunction()

# arbiter_add_program(): check shaders as one program (`arbiter check --link`), one build step.
#
#   arbiter_add_program(TARGET <target> SHADERS <files...> [LIMITS <profile>] [WERROR])
#
# The shaders (GLSL, of one or both stages; each file one shader object, its stage from its
# name) are linked as glLinkProgram links them: main() and every called function defined, the
# varyings, uniforms and samplers of the stages agreeing, the program within the limits. The
# step touches ${CMAKE_CURRENT_BINARY_DIR}/arbiter/<target>.program.stamp when the program
# links, depends on every shader and on arbiter, and adds the custom target <target> (built by
# ALL). LIMITS and WERROR as for arbiter_add_shaders.
function(arbiter_add_program)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "WERROR" "TARGET;LIMITS" "SHADERS")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "arbiter_add_program: unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_TARGET OR NOT ARG_SHADERS)
    message(FATAL_ERROR "arbiter_add_program: TARGET and SHADERS are required")
  endif()
  if(NOT TARGET arbiter::arbiter)
    message(FATAL_ERROR "arbiter_add_program: no arbiter::arbiter target (find_package(arbiter))")
  endif()
  _arbiter_common_flags("${ARG_LIMITS}" "${ARG_WERROR}" flags depends)
  list(PREPEND flags --link)
  set(paths "")
  foreach(source IN LISTS ARG_SHADERS)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}"
               NORMALIZE OUTPUT_VARIABLE path)
    if(NOT EXISTS "${path}")
      message(FATAL_ERROR "arbiter_add_program: no such shader: ${source}")
    endif()
    list(APPEND paths "${path}")
  endforeach()
  set(stamp "${CMAKE_CURRENT_BINARY_DIR}/arbiter/${ARG_TARGET}.program.stamp")
  add_custom_command(
    OUTPUT "${stamp}"
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${CMAKE_CURRENT_BINARY_DIR}/arbiter"
    COMMAND arbiter::arbiter check ${flags} ${paths}
    COMMAND "${CMAKE_COMMAND}" -E touch "${stamp}"
    DEPENDS ${paths} "$<TARGET_FILE:arbiter::arbiter>" ${depends}
    COMMENT "arbiter check --link ${ARG_TARGET}"
    VERBATIM)
  add_custom_target(${ARG_TARGET} ALL DEPENDS "${stamp}")
  set_property(TARGET ${ARG_TARGET} PROPERTY ARBITER_OUTPUTS "${stamp}")
endfunction()
