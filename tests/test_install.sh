#!/bin/sh
# `make install` into a staging DESTDIR with PREFIX=/usr, then a C program
# built only from `pkg-config --cflags --libs carom` (pointed at the staging
# tree) links and runs against the installed library; then `make uninstall`
# leaves no file behind.
# Usage: sh tests/test_install.sh [BUILD-DIR]     (default build)
# Prints "install: N passed, N failed" last; exits non-zero if anything failed.
set -eu

cd "$(dirname "$0")/.."
BUILD=${1:-build}
MAKE=${MAKE:-make}
CC=${CC:-cc}
pass=0
fail=0
ok () { pass=$((pass + 1)); echo "ok   - $1"; }
bad () { fail=$((fail + 1)); echo "FAIL - $1"; }
finish () {
  echo "install: $pass passed, $fail failed"
  [ "$fail" -eq 0 ]
  exit
}

tools/ensure-deps build cmake

tmp=$(mktemp -d "${TMPDIR:-/tmp}/carom-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
root="$tmp/root"
version=$($MAKE -s --no-print-directory print-version)
major=${version%%.*}
libdir="$root/usr/lib"

# ---------------------------------------------------------------- install
if $MAKE --no-print-directory BUILD="$BUILD" PREFIX=/usr DESTDIR="$root" install >"$tmp/install.log" 2>&1; then
  ok "make install PREFIX=/usr DESTDIR=<tmp>"
else
  sed 's/^/    /' "$tmp/install.log"
  bad "make install PREFIX=/usr DESTDIR=<tmp>"
  finish
fi

missing=""
for f in usr/include/carom.h usr/lib/libcarom.so.$version usr/lib/libcarom.a usr/lib/pkgconfig/carom.pc \
  usr/lib/cmake/carom/carom-config.cmake usr/lib/cmake/carom/carom-config-version.cmake \
  usr/share/carom/scenes/thesis.scene; do
  [ -f "$root/$f" ] || missing="$missing $f"
done
if pkg-config --exists cairo 2>/dev/null && [ ! -x "$root/usr/bin/carom" ]; then missing="$missing usr/bin/carom"; fi
if [ -z "$missing" ]; then ok "header, shared and static library, carom.pc, the CMake package, the scenes and the runner installed"
else bad "installed files missing:$missing"; fi

if [ -L "$libdir/libcarom.so.$major" ] && [ "$(readlink "$libdir/libcarom.so.$major")" = "libcarom.so.$version" ] \
  && [ -L "$libdir/libcarom.so" ] && [ "$(readlink "$libdir/libcarom.so")" = "libcarom.so.$major" ]; then
  ok "symlinks libcarom.so -> libcarom.so.$major -> libcarom.so.$version (relative)"
else
  bad "symlinks libcarom.so -> libcarom.so.$major -> libcarom.so.$version"
fi

# ----------------------------------------------------------- pkg-config
# PKG_CONFIG_LIBDIR too, so a carom.pc elsewhere on the machine cannot answer.
PKG_CONFIG_SYSROOT_DIR="$root"
PKG_CONFIG_PATH="$libdir/pkgconfig"
PKG_CONFIG_LIBDIR="$libdir/pkgconfig"
export PKG_CONFIG_SYSROOT_DIR PKG_CONFIG_PATH PKG_CONFIG_LIBDIR

if [ "$(pkg-config --modversion carom 2>&1)" = "$version" ]; then
  ok "pkg-config --modversion carom is $version"
else
  bad "pkg-config --modversion carom: $(pkg-config --modversion carom 2>&1)"
fi
if pkg-config --static --libs carom | grep -q -- '-lm'; then
  ok "pkg-config --static --libs carom adds -lm"
else
  bad "pkg-config --static --libs carom adds -lm: $(pkg-config --static --libs carom)"
fi

# --------------------------------------------------- a program against it
flags=$(pkg-config --cflags --libs carom)
# shellcheck disable=SC2086 # $flags is a list of options
if $CC -std=c99 -Wall -Wextra -pedantic -o "$tmp/smoke" tests/install_smoke.c $flags >"$tmp/cc.log" 2>&1; then
  ok "cc tests/install_smoke.c \$(pkg-config --cflags --libs carom)"
else
  sed 's/^/    /' "$tmp/cc.log"
  bad "cc tests/install_smoke.c $flags"
  finish
fi

needed=$(readelf -d "$tmp/smoke" | sed -n 's/.*(NEEDED).*\[\(libcarom[^]]*\)\].*/\1/p')
if [ "$needed" = "libcarom.so.$major" ]; then ok "the program needs libcarom.so.$major (the soname)"
else bad "the program needs '$needed', want libcarom.so.$major"; fi

out=$(LD_LIBRARY_PATH="$libdir" "$tmp/smoke" 2>&1) || true
lib_used=$(LD_LIBRARY_PATH="$libdir" ldd "$tmp/smoke" | sed -n 's/.*libcarom[^ ]* => \([^ ]*\).*/\1/p')
if printf '%s\n' "$out" | grep -qx 'position 0.000000 5.000000' && [ "$lib_used" = "$libdir/libcarom.so.$major" ]; then
  ok "it runs on the installed library: $(printf '%s' "$out" | tr '\n' ';')"
else
  printf '%s\n' "$out" | sed 's/^/    /'
  bad "it runs on the installed library ($lib_used) and prints 'position 0.000000 5.000000'"
fi

# The same program linked statically against libcarom.a (Libs.private).
sflags=$(pkg-config --cflags --libs --static carom | sed 's/-lcarom/-Wl,-Bstatic -lcarom -Wl,-Bdynamic/')
# shellcheck disable=SC2086 # $sflags is a list of options
if $CC -std=c99 -o "$tmp/smoke-static" tests/install_smoke.c $sflags >"$tmp/cc-static.log" 2>&1 \
  && ! readelf -d "$tmp/smoke-static" | grep -q 'NEEDED.*libcarom' \
  && "$tmp/smoke-static" | grep -qx 'position 0.000000 5.000000'; then
  ok "linked statically with libcarom.a, it runs"
else
  sed 's/^/    /' "$tmp/cc-static.log"
  bad "linked statically with libcarom.a ($sflags), it runs"
fi

# ----------------------------------------------------------------- CMake
# find_package(carom) against the staged install: both imported targets.
if cmake -S tests/cmake/find -B "$tmp/cmake-find" -DCMAKE_PREFIX_PATH="$root/usr" \
     -DSMOKE_SOURCE="$PWD/tests/install_smoke.c" >"$tmp/cmake.log" 2>&1 \
   && cmake --build "$tmp/cmake-find" >>"$tmp/cmake.log" 2>&1 \
   && LD_LIBRARY_PATH="$libdir" "$tmp/cmake-find/smoke" | grep -qx 'position 0.000000 5.000000' \
   && "$tmp/cmake-find/smoke_static" | grep -qx 'position 0.000000 5.000000' \
   && readelf -d "$tmp/cmake-find/smoke" | grep -q "NEEDED.*libcarom.so.$major"; then
  ok "find_package(carom) and target_link_libraries(app carom::carom / carom::carom_static): built, they run"
else
  sed 's/^/    /' "$tmp/cmake.log"
  bad "find_package(carom) and carom::carom against the staged install"
fi
# the version file refuses another major version
printf 'cmake_minimum_required(VERSION 3.13)\nproject(m C)\nfind_package(carom %s REQUIRED)\n' "$((major + 1)).0" \
  >"$tmp/major.cmake"
mkdir -p "$tmp/major-src" && cp "$tmp/major.cmake" "$tmp/major-src/CMakeLists.txt"
if ! cmake -S "$tmp/major-src" -B "$tmp/cmake-major2" -DCMAKE_PREFIX_PATH="$root/usr" >"$tmp/major.log" 2>&1 \
   && grep -q 'considered but not accepted' "$tmp/major.log"; then
  ok "find_package(carom $((major + 1)).0) is refused by the version file"
else
  bad "find_package(carom $((major + 1)).0) was accepted"
fi
# add_subdirectory of the source tree
if cmake -S tests/cmake/subdir -B "$tmp/cmake-sub" -DCAROM_SOURCE="$PWD" \
     -DSMOKE_SOURCE="$PWD/tests/install_smoke.c" >"$tmp/cmake-sub.log" 2>&1 \
   && cmake --build "$tmp/cmake-sub" >>"$tmp/cmake-sub.log" 2>&1 \
   && "$tmp/cmake-sub/smoke" | grep -qx 'position 0.000000 5.000000'; then
  ok "add_subdirectory(carom) with the top-level CMakeLists.txt: built, it runs"
else
  sed 's/^/    /' "$tmp/cmake-sub.log"
  bad "add_subdirectory(carom) with the top-level CMakeLists.txt"
fi

# -------------------------------------------------------------- uninstall
if $MAKE --no-print-directory BUILD="$BUILD" PREFIX=/usr DESTDIR="$root" uninstall >"$tmp/uninstall.log" 2>&1 \
  && [ -z "$(find "$root" ! -type d)" ]; then
  ok "make uninstall removes every installed file"
else
  sed 's/^/    /' "$tmp/uninstall.log"
  find "$root" ! -type d | sed 's/^/    left: /'
  bad "make uninstall removes every installed file"
fi

finish
