#!/usr/bin/env bash
# Installs the built litkit into a scratch prefix and builds and runs a small
# project that finds it with find_package(litkit), from a fresh build folder.
# Also checks what the package installs: exactly the public headers (each
# one in litkit.hpp but gl_renderer.hpp, litkit::gl's own), the docs and the
# examples; and that docs/cpp-api.md shows the consumer's program unchanged.
# Usage: check_install.sh BUILD_DIR
set -euo pipefail
build=$1
here=$(cd "$(dirname "$0")" && pwd)
source_dir=$(cd "$here/.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() { echo "check_install: $*" >&2; exit 1; }

# docs/cpp-api.md's program is tests/install_consumer/main.cpp, to the byte.
awk '/^<!-- program: tests\/install_consumer\/main.cpp -->$/ {marked = 1; next}
     marked && /^```cpp$/ {inside = 1; next}
     inside && /^```$/ {exit}
     inside {print}' "$source_dir/docs/cpp-api.md" > "$scratch/page.cpp"
cmp -s "$scratch/page.cpp" "$here/install_consumer/main.cpp" ||
    fail "docs/cpp-api.md does not show tests/install_consumer/main.cpp as it is"

prefix=$scratch/prefix
cmake --install "$build" --prefix "$prefix" > /dev/null

# Headers: exactly include/litkit/*.hpp, and litkit.hpp includes them all
# (but gl_renderer.hpp, which belongs to litkit::gl).
(cd "$source_dir/include/litkit" && ls) > "$scratch/public"
(cd "$prefix/include/litkit" && ls) > "$scratch/installed"
diff "$scratch/public" "$scratch/installed" || fail "installed headers differ from include/litkit"
for internal in files.hpp convex.hpp; do
    test ! -e "$prefix/include/litkit/$internal" || fail "internal header $internal is installed"
done
for header in $(cat "$scratch/installed"); do
    case $header in litkit.hpp | gl_renderer.hpp) continue ;; esac
    grep -qx "#include \"litkit/$header\"" "$prefix/include/litkit/litkit.hpp" ||
        fail "litkit.hpp does not include $header"
done

# Docs and examples.
for doc in "$source_dir"/docs/*.md; do
    test -f "$prefix/share/doc/litkit/$(basename "$doc")" || fail "$(basename "$doc") not installed"
done
test -f "$prefix/share/doc/litkit/README.md" || fail "README.md not installed"
test -n "$(ls "$prefix/share/doc/litkit/images/"*.png)" || fail "docs/images not installed"
for example in "$source_dir"/examples/*.toml; do
    test -f "$prefix/share/litkit/examples/$(basename "$example")" ||
        fail "example $(basename "$example") not installed"
done
# An installed example renders with the installed CLI (its mesh files came along).
"$prefix/bin/litkit" render "$prefix/share/litkit/examples/mesh.toml" -o "$scratch/mesh.png" \
    --width 80 --height 60 > /dev/null

cmake -S "$here/install_consumer" -B "$scratch/consumer" -G Ninja \
      -DCMAKE_PREFIX_PATH="$prefix" > /dev/null
cmake --build "$scratch/consumer" > /dev/null
(cd "$scratch/consumer" && ./consumer && test -s front.png && test -s side.png)
"$scratch/consumer/gl_and_teaching"
test -x "$prefix/bin/litkit"
"$prefix/bin/litkit" --version
