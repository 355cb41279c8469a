#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The API reference builds without a single Doxygen warning, and the
# configuration really fails on an undocumented public name.
# Usage: check_docs.sh DOXYGEN DOXYFILE SOURCE_DIR
#
# Runs Doxygen with the Doxyfile that the `docs` target uses (configured by
# docs/CMakeLists.txt), writing into a scratch folder so that it never races
# a `docs` build of the same tree.
set -euo pipefail
doxygen=$1
doxyfile=$2
source_dir=$3
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# run NAME [EXTRA CONFIG LINES...]: Doxygen's exit status; its warnings in
# $scratch/NAME.log. Later lines of a configuration override earlier ones.
run() {
  local name=$1; shift
  { cat "$doxyfile"; echo "OUTPUT_DIRECTORY = $scratch/$name"; printf '%s\n' "$@"; } |
    "$doxygen" - > "$scratch/$name.out" 2> "$scratch/$name.log"
}

# 1. The public headers as they are: no warning at all, and the pages of the
# main names exist (so the headers were read, not skipped).
if ! run clean || [ -s "$scratch/clean.log" ]; then
  echo "FAIL: Doxygen warns on the public headers (every public name needs a /// comment):" >&2
  cat "$scratch/clean.log" >&2
  exit 1
fi
for page in index.html classlitkit_1_1Error.html structlitkit_1_1Scene.html namespacelitkit.html; do
  if [ ! -s "$scratch/clean/html/$page" ]; then
    echo "FAIL: the API reference has no $page" >&2
    exit 1
  fi
done

# 2. A copy of the headers with one undocumented function added: the run must
# fail, naming it. Guards the configuration itself (EXTRACT_ALL = NO,
# WARN_IF_UNDOCUMENTED, WARN_AS_ERROR) against a change that silences it.
# An undocumented function in a `detail` namespace is added too: internal,
# so it must not be reported (EXCLUDE_SYMBOLS).
mkdir -p "$scratch/include"
cp -r "$source_dir/include/litkit" "$scratch/include/"
printf '\nnamespace litkit {\nint undocumented_on_purpose(int x);\n}\n' >> "$scratch/include/litkit/image.hpp"
printf '\nnamespace litkit::detail {\nint internal_on_purpose(int x);\n}\n' >> "$scratch/include/litkit/image.hpp"
if run undocumented "INPUT = $scratch/include/litkit" "STRIP_FROM_PATH = $scratch/include" \
     "STRIP_FROM_INC_PATH = $scratch/include" "USE_MDFILE_AS_MAINPAGE ="; then
  echo "FAIL: Doxygen passed with an undocumented public function" >&2
  exit 1
fi
if ! grep -q "undocumented_on_purpose" "$scratch/undocumented.log"; then
  echo "FAIL: Doxygen failed without naming the undocumented function:" >&2
  cat "$scratch/undocumented.log" >&2
  exit 1
fi
if grep -q "internal_on_purpose" "$scratch/undocumented.log"; then
  echo "FAIL: Doxygen reports a name of a detail namespace (EXCLUDE_SYMBOLS):" >&2
  cat "$scratch/undocumented.log" >&2
  exit 1
fi
echo "docs: clean; an undocumented name fails the run; detail namespaces are left out"
