#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The bash completion script the build writes (docs/CMakeLists.txt) is what
# `litkit --bash-completion` prints, is valid bash, and completes what the
# program has: every command `litkit --help` lists, every long option each
# command's --help lists, the names --reflection and --shading take (listed
# here by hand, from docs/spec.md), and file names for -o and the scenes.
# Usage: check_completion.sh LITKIT COMPLETION_FILE
set -euo pipefail
litkit=$1
script=$(realpath "$2")
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$litkit" --bash-completion > "$scratch/now"
cmp -s "$scratch/now" "$script" || fail "$script is not what 'litkit --bash-completion' prints now"
bash -n "$script" || fail "$script is not valid bash"

complete_words() {  # WORDS...: what completing the last word offers, sorted, one a line
  (cd "$scratch" && bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _litkit
                             printf "%s\n" "${COMPREPLY[@]}" | sort' _ "$script" "$@")
}
expect() {  # EXPECTED WORDS...
  local expected=$1; shift
  local got
  got=$(complete_words "$@" | tr '\n' ' ' | sed 's/ $//')
  [ "$got" = "$expected" ] || fail "completing '$*' gave '$got', not '$expected'"
}

mapfile -t commands < <("$litkit" --help | sed -n '/^Subcommands:/,$p' | sed -n 's/^  \([a-z][a-z0-9-]*\) .*/\1/p')
[ ${#commands[@]} -ge 9 ] || fail "found only ${#commands[@]} commands in 'litkit --help'"
expect "$(printf '%s\n' "${commands[@]}" | sort | tr '\n' ' ' | sed 's/ $//')" litkit ""
expect "render" litkit re
for command in "${commands[@]}"; do
  offered=$(complete_words litkit "$command" --)
  for option in $("$litkit" "$command" --help | grep -oE -- '--[a-z][a-z-]*' | sort -u); do
    grep -qx -- "$option" <<< "$offered" || fail "'litkit $command --' does not offer $option"
  done
  grep -qx -- "--quiet" <<< "$offered" || fail "'litkit $command --' does not offer --quiet"
done
expect "--reflection" litkit render --refl
expect "blinn-phong cook-torrance gooch half-lambert lambert minnaert oren-nayar phong toon" \
  litkit render --reflection ""
expect "faceted flat gouraud phong" litkit compare --shading ""
expect "cpu gl" litkit -q render --backend ""
expect "" litkit render --width ""
touch "$scratch/scene.toml" "$scratch/spin.gif"
expect "spin.gif" litkit turntable -o sp
expect "scene.toml" litkit check sc
echo "bash completion: ${#commands[@]} commands checked"
