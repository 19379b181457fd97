#!/bin/sh
# The stable C ABI (docs/abi.md), checked on the shared library.
# Usage: sh tests/test_abi.sh [BUILD-DIR]     (default build; run from anywhere)
#
#  - the .so exports every CAROM_API function of include/carom.h and nothing
#    else (no internal helper leaks into the dynamic symbol table);
#  - its soname is libcarom.so.MAJOR and its file name is versioned;
#  - `make abi-check` passes against the committed baseline;
#  - a build with other optimisation flags has the same ABI;
#  - on copies of the sources, deliberate breaks (a parameter type changed,
#    a function no longer exported, a field inserted in the middle of a
#    struct) make abi-check fail, and allowed changes (a new function, a field
#    appended to a size-prefixed struct) pass.
# Prints "abi: N passed, N failed" last; exits non-zero if anything failed.
set -eu

cd "$(dirname "$0")/.."
BUILD=${1:-build}
MAKE=${MAKE:-make}
pass=0
fail=0
ok () { pass=$((pass + 1)); echo "ok   - $1"; }
bad () { fail=$((fail + 1)); echo "FAIL - $1"; }

tools/ensure-deps build abi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/carom-abi.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

if ! $MAKE --no-print-directory BUILD="$BUILD" lib >"$tmp/build.log" 2>&1; then
  cat "$tmp/build.log"
  bad "the library builds in $BUILD"
  echo "abi: $pass passed, $fail failed"
  exit 1
fi

version=$($MAKE -s --no-print-directory print-version)
major=${version%%.*}
so="$BUILD/libcarom.so.$version"

# --------------------------------------------------------------- exports
nm -D --defined-only "$so" | awk '{ print $NF }' | sort >"$tmp/exported"
grep -v -e '^carom_' -e '^_init$' -e '^_fini$' "$tmp/exported" >"$tmp/extra" || true
if [ -s "$tmp/extra" ]; then
  bad "only carom_* symbols are exported; also found: $(tr '\n' ' ' <"$tmp/extra")"
else
  ok "only carom_* symbols are exported ($(grep -c '^carom_' "$tmp/exported") of them)"
fi

# Every declaration in the header is `CAROM_API <type> carom_name (` on one
# line; count them first so a reformatted header cannot pass vacuously.
sed -n 's/^CAROM_API.*[ *]\(carom_[a-z0-9_]*\) *(.*/\1/p' include/carom.h | sort >"$tmp/declared"
comm -23 "$tmp/declared" "$tmp/exported" >"$tmp/missing"
comm -13 "$tmp/declared" "$tmp/exported" >"$tmp/undeclared"
if [ ! -s "$tmp/declared" ]; then
  bad "found no CAROM_API declarations in include/carom.h"
elif [ -s "$tmp/missing" ]; then
  bad "every CAROM_API function is exported; missing: $(tr '\n' ' ' <"$tmp/missing")"
else
  ok "every CAROM_API function of include/carom.h is exported ($(wc -l <"$tmp/declared"))"
fi
if [ -s "$tmp/undeclared" ]; then
  bad "every exported function is declared in include/carom.h; not declared: $(tr '\n' ' ' <"$tmp/undeclared")"
else
  ok "every exported function is declared in include/carom.h"
fi

# Not counted (the library's own business, reported so it stays visible):
# global names in the static library that an application could clash with.
unprefixed=$(nm -g --defined-only "$BUILD/libcarom.a" 2>/dev/null | awk 'NF == 3 && $3 !~ /^carom_/ { print $3 }' | sort -u)
if [ -n "$unprefixed" ]; then
  echo "note - libcarom.a defines $(echo "$unprefixed" | wc -l) global symbols without the carom_ prefix" \
    "(possible clashes when linking statically): $(echo "$unprefixed" | tr '\n' ' ')"
fi

soname=$(readelf -d "$so" | sed -n 's/.*(SONAME).*\[\(.*\)\].*/\1/p')
if [ "$soname" = "libcarom.so.$major" ] \
  && [ "$(readlink "$BUILD/libcarom.so.$major")" = "libcarom.so.$version" ] \
  && [ "$(readlink "$BUILD/libcarom.so")" = "libcarom.so.$major" ]; then
  ok "soname $soname, real name libcarom.so.$version, symlinks in place"
else
  bad "soname is '$soname' (want libcarom.so.$major) or the symlinks are wrong"
fi

# ------------------------------------------------------------ abi-check
if $MAKE --no-print-directory BUILD="$BUILD" abi-check >"$tmp/check.log" 2>&1; then
  ok "make abi-check passes against abi/libcarom.abi"
else
  sed 's/^/    /' "$tmp/check.log"
  bad "make abi-check passes against abi/libcarom.abi"
fi

# ------------------------------------------------- copies of the sources
# Each case is a copy of the build (Makefile, mk/abi.mk, abi/, include/,
# lib/, tools/ensure-deps) with an edit, checked with the same rule. The
# parent's MAKEFLAGS (BUILD=..., DESTDIR=...) must not reach these builds.
case_no=0
# variant NAME EXPECT(pass|fail) GREP-FOR-IN-REPORT OPT [FILE SED-SCRIPT]...
variant () {
  name=$1 expect=$2 needle=$3 opt=$4
  shift 4
  case_no=$((case_no + 1))
  d="$tmp/case$case_no"
  mkdir -p "$d/mk" "$d/tools"
  cp -R Makefile include lib abi "$d/"
  cp mk/abi.mk "$d/mk/"
  cp tools/ensure-deps "$d/tools/"
  while [ $# -ge 2 ]; do
    cp "$d/$1" "$d/$1.orig"
    sed "$2" "$d/$1.orig" >"$d/$1"
    if cmp -s "$d/$1" "$d/$1.orig"; then
      bad "$name: the edit '$2' did not apply to $1 (update tests/test_abi.sh)"
      return 0
    fi
    rm -f "$d/$1.orig"
    shift 2
  done
  rc=0
  (unset MAKEFLAGS MFLAGS MAKELEVEL; cd "$d" && $MAKE --no-print-directory -j2 BUILD=build OPT="$opt" abi-check) \
    >"$d/log" 2>&1 || rc=$?
  if [ "$expect" = pass ] && [ $rc -eq 0 ] && grep -q -- "$needle" "$d/log"; then
    ok "$name: abi-check passes"
  elif [ "$expect" = fail ] && [ $rc -ne 0 ] && grep -q 'abi-check: FAILED' "$d/log" \
    && grep -q -- "$needle" "$d/log"; then
    ok "$name: abi-check fails ($(sed -n 's/.*abidiff exit status \([0-9]*\).*/abidiff exit status \1/p' "$d/log"))"
  else
    sed 's/^/    /' "$d/log"
    bad "$name: abi-check should $expect (make exit status $rc, looked for '$needle')"
  fi
}

variant "a build with OPT='-O0 -g' has the same ABI" pass "abi-check: OK" '-O0 -g'
variant "a build with OPT='-O3 -g -DNDEBUG' has the same ABI" pass "abi-check: OK" '-O3 -g -DNDEBUG'
# enums carry a 0x7fffffff member, so even -fshort-enums keeps them 32-bit
variant "a build with -fshort-enums has the same ABI (enums pinned to 32 bits)" pass "abi-check: OK" '-O2 -g -fshort-enums'
variant "an enum losing its 32-bit pin under -fshort-enums is caught" fail "abi-check: FAILED" '-O2 -g -fshort-enums' \
  include/carom.h '/_FORCE_32 = 0x7fffffff/d' lib/status.c '/CAROM_STATUS_FORCE_32/d'
variant "carom_world_update takes float dt instead of double" fail "carom_world_update" '-O2 -g' \
  include/carom.h 's/carom_world_update (carom_world \*world, double dt)/carom_world_update (carom_world *world, float dt)/' \
  lib/world.c 's/carom_world_update (carom_world \*world, double dt)/carom_world_update (carom_world *world, float dt)/'
variant "carom_world_detect is no longer exported" fail "1 Removed" '-O2 -g' \
  include/carom.h 's/^CAROM_API carom_status carom_world_detect /carom_status carom_world_detect /'
variant "a field inserted in the middle of carom_body_def" fail "carom_body_def" '-O2 -g' \
  include/carom.h 's/^\( *\)double x, y; .*/\1double inserted;\n&/'
# shellcheck disable=SC2016 # sed's $ (last line), not the shell's
variant "a new function (allowed)" pass "carom_abi_test_added" '-O2 -g' \
  include/carom.h 's/^CAROM_API uint32_t carom_version (void);/&\nCAROM_API int32_t carom_abi_test_added (void);/' \
  lib/status.c '$a\
int32_t carom_abi_test_added (void) { return 1; }'
variant "a field appended to carom_body_def (allowed)" pass "abi-check: OK" '-O2 -g' \
  include/carom.h 's/^} carom_body_def;/  double appended;\n&/'

echo "abi: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
