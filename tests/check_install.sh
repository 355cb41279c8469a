#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the built litkit into a scratch prefix and builds and runs a small
# project that finds it with find_package(litkit), from a fresh build folder.
# Also checks what the package installs: exactly the public headers (each
# one in litkit.hpp but gl_renderer.hpp, litkit::gl's own), the docs and the
# examples and the licence, the bash completion and pkg-config's litkit.pc
# (a program built with its flags alone runs); and that docs/cpp-api.md shows the consumer's program unchanged;
# and that the installed CLI finds its modules (lib/litkit): `--backend gl`
# draws, and `litkit view` shows a scene in a window on a virtual display
# (Xvfb).
# Usage: check_install.sh BUILD_DIR
set -euo pipefail
build=$1
here=$(cd "$(dirname "$0")" && pwd)
source_dir=$(cd "$here/.." && pwd)
scratch=$(mktemp -d)
xvfb_pid=
trap 'test -z "$xvfb_pid" || kill "$xvfb_pid"; rm -rf "$scratch"' EXIT
fail() { echo "check_install: $*" >&2; exit 1; }

# docs/cpp-api.md's program is tests/install_consumer/main.cpp, to the byte
# but for the file's licence line (scripts/spdx.sh), which the page leaves out.
awk '/^<!-- program: tests\/install_consumer\/main.cpp -->$/ {marked = 1; next}
     marked && /^```cpp$/ {inside = 1; next}
     inside && /^```$/ {exit}
     inside {print}' "$source_dir/docs/cpp-api.md" > "$scratch/page.cpp"
grep -v '^// SPDX-License-Identifier: ' "$here/install_consumer/main.cpp" > "$scratch/main.cpp"
cmp -s "$scratch/page.cpp" "$scratch/main.cpp" ||
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
cmp -s "$source_dir/LICENSE" "$prefix/share/doc/litkit/LICENSE" || fail "LICENSE not installed"
test -n "$(ls "$prefix/share/doc/litkit/images/"*.png)" || fail "docs/images not installed"
for example in "$source_dir"/examples/*.toml; do
    test -f "$prefix/share/litkit/examples/$(basename "$example")" ||
        fail "example $(basename "$example") not installed"
done
# An installed example renders with the installed CLI (its mesh files came along).
"$prefix/bin/litkit" render "$prefix/share/litkit/examples/mesh.toml" -o "$scratch/mesh.png" \
    --width 80 --height 60 > /dev/null

# Bash completion, where bash-completion looks (share/bash-completion/completions/COMMAND).
cmp -s "$build/docs/litkit.bash-completion" "$prefix/share/bash-completion/completions/litkit" ||
    fail "the bash completion is not installed as share/bash-completion/completions/litkit"

# pkg-config: a program compiled and linked with `pkg-config --cflags --libs litkit` alone.
pc=$(find "$prefix" -name litkit.pc)
[ -n "$pc" ] || fail "litkit.pc is not installed"
[ "$(PKG_CONFIG_PATH=$(dirname "$pc") pkg-config --modversion litkit)" = "$("$build/litkit" --version | head -n 1 | cut -d' ' -f2)" ] ||
    fail "litkit.pc's version is not the program's"
cat > "$scratch/pc.cpp" <<'PROGRAM'
#include <litkit/render.hpp>
#include <litkit/scene.hpp>
#include <cstdio>
int main() {
    const litkit::Image image = litkit::render(litkit::default_scene());
    std::printf("%dx%d\n", image.width, image.height);
}
PROGRAM
c++ "$scratch/pc.cpp" -o "$scratch/pc" $(PKG_CONFIG_PATH=$(dirname "$pc") pkg-config --cflags --libs litkit) ||
    fail "a program built with pkg-config's flags for litkit does not compile or link"
[ "$("$scratch/pc")" = "800x600" ] || fail "the program built with pkg-config's flags did not render"

cmake -S "$here/install_consumer" -B "$scratch/consumer" -G Ninja \
      -DCMAKE_PREFIX_PATH="$prefix" > /dev/null
cmake --build "$scratch/consumer" > /dev/null
(cd "$scratch/consumer" && ./consumer && test -s front.png && test -s side.png)
"$scratch/consumer/gl_and_teaching"
test -x "$prefix/bin/litkit"
"$prefix/bin/litkit" --version

# The modules, which the installed CLI finds relative to itself (in
# lib/litkit, or lib/<multiarch>/litkit where GNUInstallDirs picks that).
for module in litkit-view.so litkit-gl.so; do
    find "$prefix" -path "*/lib*/litkit/$module" | grep -q . || fail "$module is not in lib/litkit"
done
"$prefix/bin/litkit" render --backend gl --width 80 --height 60 -o "$scratch/gl.png" |
    grep -q "OpenGL backend: " || fail "the installed litkit render --backend gl failed"
Xvfb -displayfd 1 -screen 0 640x480x24 -nolisten tcp -noreset > "$scratch/display" 2> /dev/null &
xvfb_pid=$!
for _ in $(seq 200); do test -s "$scratch/display" && break; sleep 0.05; done
test -s "$scratch/display" || fail "Xvfb did not start (scripts/install-deps.sh installs it)"
shown=$(DISPLAY=":$(cat "$scratch/display")" "$prefix/bin/litkit" view --no-ui --width 80 --height 60 \
        --orbit-frames 3 "$prefix/share/litkit/examples/mesh.toml") ||
    fail "the installed litkit view failed"
grep -q "^orbit: 3 frames of 80x60" <<< "$shown" && echo "$shown" || fail "the installed litkit view said: $shown"
