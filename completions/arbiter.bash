# bash completion for arbiter (installed as share/bash-completion/completions/arbiter).
# Completes the commands, each command's options (as its --help lists them), the values of
# the options that take a fixed set, and the files each command reads. Works with or without
# the bash-completion package.

# _arbiter_files EXTENSIONS: file names with one of the extensions (a regex alternation, e.g.
# 'vp|fp'), and directories.
_arbiter_files() {
  local IFS=$'\n'
  local f
  compopt -o filenames 2>/dev/null
  for f in $(compgen -f -- "$cur"); do
    if [[ -d "$f" || "$f" =~ \.($1)$ ]]; then
      COMPREPLY+=("$f")
    fi
  done
}

_arbiter() {
  local cur="${COMP_WORDS[COMP_CWORD]}"
  local prev="${COMP_WORDS[COMP_CWORD - 1]}"
  COMPREPLY=()
  # "--format=js": bash splits at '=' (COMP_WORDBREAKS).
  if [[ "$cur" == "=" ]]; then
    cur=""
  elif [[ "$prev" == "=" && COMP_CWORD -ge 2 ]]; then
    prev="${COMP_WORDS[COMP_CWORD - 2]}"
  fi

  local commands="check info link translate exec verify run"
  local command="" i
  for ((i = 1; i < COMP_CWORD; i++)); do
    if [[ " $commands " == *" ${COMP_WORDS[i]} "* ]]; then
      command="${COMP_WORDS[i]}"
      break
    fi
  done
  if [[ -z "$command" ]]; then
    COMPREPLY=($(compgen -W "$commands help -h --help -V --version" -- "$cur"))
    return 0
  fi

  local arb='vp|fp|arbvp|arbfp|txt'
  local glsl='vert|vs|vsh|frag|fs|fsh|glsl'
  local options files formats="text json" stages="arbvp arbfp"
  case "$command" in
    check)
      options="-h --help --format --color --limits --stage --error-limit -W --Werror -j --jobs
               --link -D --define -U --undefine -I --include-dir --preamble --warning
               --driver-check --driver"
      files="$arb|$glsl" formats="text json sarif" stages="arbvp arbfp vert frag" ;;
    info)
      options="-h --help --format --color --limits --stage -D --define -U --undefine
               -I --include-dir --preamble --warning"
      files="$arb|$glsl" formats="text json" stages="arbvp arbfp vert frag" ;;
    link)
      options="-h --help --vert --frag --format --color --limits --error-limit -W --Werror
               -D --define -U --undefine -I --include-dir --preamble --warning"
      files="$glsl" formats="text json sarif" ;;
    translate)
      options="-h --help -o --output --bindings --pair --no-comments --target --state --stage
               --limits --color --error-limit -W --Werror -j --jobs"
      case "$prev" in
        --target)
          COMPREPLY=($(compgen -W "glsl110 glsl120 glsl330 es100 es300 vk450 spirv hlsl msl" -- "$cur"))
          return ;;
        --state)
          COMPREPLY=($(compgen -W "builtins uniforms" -- "$cur"))
          return ;;
      esac
      files="$arb" ;;
    exec)
      options="-h --help --engine --backend --driver --set --state --texture --uniform --pair
               --vectors --format --color --stage --error-limit --timeout --memory-limit"
      files="$arb|$glsl" stages="arbvp arbfp vert frag" ;;
    verify)
      options="-h --help --engines --vectors --seed --pair --max-reports --backend --driver
               --format --color --stage -j --jobs --timeout --memory-limit"
      files="$arb" ;;
    run)
      options="-h --help --translate --translate= --backend --driver -j --jobs --format --junit --png
               --timeout --memory-limit"
      files="shader_test" ;;
  esac

  case "$prev" in
    --format) COMPREPLY=($(compgen -W "$formats" -- "$cur")); return 0 ;;
    --stage) COMPREPLY=($(compgen -W "$stages" -- "$cur")); return 0 ;;
    --color) COMPREPLY=($(compgen -W "auto always never" -- "$cur")); return 0 ;;
    --driver) COMPREPLY=($(compgen -W "softpipe llvmpipe" -- "$cur")); return 0 ;;
    --backend) COMPREPLY=($(compgen -W "osmesa egl" -- "$cur")); return 0 ;;
    --engine) COMPREPLY=($(compgen -W "ref mesa all vulkan" -- "$cur")); return 0 ;;
    --engines) COMPREPLY=($(compgen -W "ref mesa-arb mesa-glsl mesa-glsl330 mesa-es300 mesa-es100 vulkan-spirv softpipe llvmpipe vulkan" -- "$cur")); return 0 ;;
    --limits)
      COMPREPLY=($(compgen -W "spec-min mesa r300 r500 i915 nv30 nv40" -- "$cur"))
      _arbiter_files json
      return 0 ;;
    --vert) _arbiter_files 'vert|vs'; return 0 ;;
    --frag) _arbiter_files 'frag|fs'; return 0 ;;
    -o | --output | --bindings | --junit | --png)
      compopt -o filenames 2>/dev/null
      COMPREPLY=($(compgen -f -- "$cur"))
      return 0 ;;
    --vectors)
      # exec reads a JSON file; verify takes a number.
      [[ "$command" == exec ]] && _arbiter_files json
      return 0 ;;
    --error-limit | -j | --jobs | --seed | --max-reports | --timeout | --memory-limit | --set | \
      --state | --texture | --uniform)
      return 0 ;;
  esac

  if [[ "$cur" == -* ]]; then
    COMPREPLY=($(compgen -W "$options" -- "$cur"))
    return 0
  fi
  _arbiter_files "$files"
  return 0
}

complete -F _arbiter arbiter
