#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The licence line of every source file: `// SPDX-License-Identifier: MIT`
# (`#` in Python, shell and CMake files) as its first line, or its second
# after a `#!` line. Adds it where it is missing and leaves every other file
# as it is, so that running it again changes nothing.
#
#   scripts/spdx.sh [ROOT]              adds the missing lines (ROOT: the repository root)
#   scripts/spdx.sh --check [ROOT]      lists the files without one; fails if there are any
#   scripts/spdx.sh --self-test         shows that the check can fail and the fix is idempotent
#
# Source files: C++ (.cpp .hpp .h .c .cc), Python (.py .pyi), shell (.sh and
# any file starting with a shell or Python #! line), CMake (CMakeLists.txt,
# .cmake, .cmake.in) and JavaScript (.js .mjs), as git lists them (every file
# outside build* folders where the tree is no git checkout). Not: test data
# (tests/data, tests/bad), the files embedded as text into the programs
# `litkit export` writes (src/gl/opengl_core.inc, opengl_samples.inc and the
# .in templates: their text is the export's), shaders and notebooks.
set -euo pipefail

tag="SPDX-License-Identifier: MIT"

# The comment that starts a line of FILE, or nothing when FILE is no source file.
comment_of() {
  local file=$1
  case "$file" in
    tests/data/* | tests/bad/* | */node_modules/* | src/gl/opengl_core.inc | src/gl/opengl_samples.inc) return ;;
    *.cpp | *.hpp | *.h | *.c | *.cc | *.js | *.mjs) echo "//" ;;
    *.py | *.pyi | *.sh | *.cmake | *.cmake.in | CMakeLists.txt | */CMakeLists.txt) echo "#" ;;
  esac
  case "${file##*/}" in
    *.*) ;;
    *) head -c 64 "$file" 2>/dev/null | head -n 1 | grep -qE '^#!.*(sh|bash|python3?)( |$)' && echo "#" ;;
  esac
  return 0
}

files_of() {  # ROOT: every file, relative to ROOT
  local root=$1
  if git -C "$root" rev-parse --show-toplevel > /dev/null 2>&1 &&
     [ "$(cd "$root" && pwd -P)" = "$(cd "$(git -C "$root" rev-parse --show-toplevel)" && pwd -P)" ]; then
    git -C "$root" ls-files
  else
    (cd "$root" && find . -path './build*' -prune -o -path ./.git -prune -o -type f -print | sed 's|^\./||')
  fi
}

has_tag() {  # FILE: the tag on its first line, or its second after a #! line
  local first second
  first=$(sed -n 1p "$1")
  second=$(sed -n 2p "$1")
  [[ "$first" == *"$tag" ]] && return 0
  [[ "$first" == '#!'* && "$second" == *"$tag" ]]
}

add_tag() {  # FILE COMMENT
  local file=$1 line="$2 $tag" scratch
  scratch=$(mktemp "$file.spdx.XXXXXX")
  if [[ "$(head -c 2 "$file")" == '#!' ]]; then
    { sed -n 1p "$file"; echo "$line"; sed 1d "$file"; } > "$scratch"
  else
    { echo "$line"; cat "$file"; } > "$scratch"
  fi
  chmod --reference="$file" "$scratch"
  mv "$scratch" "$file"
}

run() {  # MODE ROOT: MODE fix or check; prints the files without the line
  local mode=$1 root=$2 file comment status=0
  while IFS= read -r file; do
    [ -f "$root/$file" ] || continue
    comment=$(cd "$root" && comment_of "$file")
    [ -n "$comment" ] || continue
    has_tag "$root/$file" && continue
    if [ "$mode" = check ]; then
      echo "$file: no '$comment $tag' line (scripts/spdx.sh adds it)"
      status=1
    else
      add_tag "$root/$file" "$comment"
      echo "added: $file"
    fi
  done < <(files_of "$root")
  return $status
}

self_test() {
  local scratch
  scratch=$(mktemp -d)
  trap 'rm -rf "$scratch"' RETURN
  mkdir -p "$scratch/src" "$scratch/tests/data"
  printf '// a header\n#pragma once\n' > "$scratch/src/a.hpp"
  printf '#!/usr/bin/env bash\necho hi\n' > "$scratch/run"
  printf '"""doc"""\n' > "$scratch/b.py"
  printf 'v 0 0 0\n' > "$scratch/tests/data/c.py"
  printf 'text\n' > "$scratch/notes.md"
  chmod +x "$scratch/run"
  if run check "$scratch" > /dev/null; then echo "self-test: a tree without the lines passed" >&2; return 1; fi
  run fix "$scratch" > /dev/null
  run check "$scratch" || { echo "self-test: the fixed tree fails" >&2; return 1; }
  [ "$(sed -n 1p "$scratch/src/a.hpp")" = "// $tag" ] || { echo "self-test: a.hpp" >&2; return 1; }
  [ "$(sed -n 2p "$scratch/src/a.hpp")" = "// a header" ] || { echo "self-test: a.hpp" >&2; return 1; }
  [ "$(sed -n 1p "$scratch/run")" = "#!/usr/bin/env bash" ] || { echo "self-test: run" >&2; return 1; }
  [ "$(sed -n 2p "$scratch/run")" = "# $tag" ] || { echo "self-test: run" >&2; return 1; }
  [ -x "$scratch/run" ] || { echo "self-test: run lost its mode" >&2; return 1; }
  [ "$(sed -n 1p "$scratch/b.py")" = "# $tag" ] || { echo "self-test: b.py" >&2; return 1; }
  [ "$(cat "$scratch/tests/data/c.py")" = "v 0 0 0" ] || { echo "self-test: test data changed" >&2; return 1; }
  [ "$(cat "$scratch/notes.md")" = "text" ] || { echo "self-test: notes.md changed" >&2; return 1; }
  local before
  before=$(cd "$scratch" && find . -type f -exec sha256sum {} + | sort)
  run fix "$scratch" > /dev/null
  [ "$before" = "$(cd "$scratch" && find . -type f -exec sha256sum {} + | sort)" ] ||
    { echo "self-test: a second run changed files" >&2; return 1; }
  echo "self-test passed"
}

root_default=$(cd "$(dirname "$0")/.." && pwd)
case "${1:-}" in
  --check) run check "${2:-$root_default}" ;;
  --self-test) self_test ;;
  -*) echo "usage: $0 [--check | --self-test] [ROOT]" >&2; exit 2 ;;
  *) run fix "${1:-$root_default}" ;;
esac
