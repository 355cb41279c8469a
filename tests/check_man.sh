#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The man page built from `litkit --help` (docs/CMakeLists.txt) renders
# without a groff warning, names every command that `litkit --help` lists
# with that command's options, carries the version, and `cmake --install`
# puts it in share/man/man1.
# Usage: check_man.sh BUILD_DIR LITKIT MAN_PAGE
set -euo pipefail
build=$1
litkit=$2
page=$3
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

[ -s "$page" ] || fail "no man page at $page (build the 'man' target, part of the default build)"

# groff with every warning on (-ww) writes nothing to stderr for a clean page.
groff -man -Tutf8 -ww -z "$page" 2> "$scratch/groff.log" || fail "groff failed on $page"
[ -s "$scratch/groff.log" ] && fail "groff warns on $page: $(cat "$scratch/groff.log")"
# The text as `man -l` shows it, wide enough that no line of help is broken,
# as plain characters (grotty: no colour, bold or underline).
groff -man -Tutf8 -rLL=200n -P-c -P-b -P-o -P-u "$page" > "$scratch/page.txt" 2> "$scratch/render.log"
[ -s "$scratch/render.log" ] && fail "groff warns on $page: $(cat "$scratch/render.log")"

# The commands, as the program lists them after "Subcommands:".
mapfile -t commands < <("$litkit" --help | sed -n '/^Subcommands:/,$p' | sed -n 's/^  \([a-z][a-z0-9-]*\) .*/\1/p')
[ ${#commands[@]} -ge 5 ] || fail "found only ${#commands[@]} commands in 'litkit --help'"
for command in "${commands[@]}"; do
  grep -q "^ *litkit $command\$" "$scratch/page.txt" ||
    fail "the man page has no section 'litkit $command'"
  grep -q "^ *Usage: litkit $command " "$scratch/page.txt" ||
    fail "the man page lacks the usage of 'litkit $command'"
done
# One option of a command, written as typed (ASCII minus signs).
grep -q -- "--reflection TEXT" "$scratch/page.txt" || fail "the man page lacks render's --reflection"
version=$("$litkit" --version | head -n 1)  # "litkit 0.1.0"; the build's features follow
grep -q "$version" "$scratch/page.txt" || fail "the man page does not carry '$version'"

cmake --install "$build" --prefix "$scratch/prefix" > /dev/null
cmp -s "$page" "$scratch/prefix/share/man/man1/litkit.1" ||
  fail "cmake --install did not put litkit.1 in share/man/man1"
echo "man: ${#commands[@]} commands (${commands[*]}), rendered clean, installed"
