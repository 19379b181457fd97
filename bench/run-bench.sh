#!/bin/sh
# Run every benchmark once and write docs/performance.md.
# usage: bench/run-bench.sh BENCH_DIR [OUTPUT]     (make bench calls it)
#
# BENCH_DIR holds the bench binaries (bench_carom, bench_broadphase, and
# bench_chipmunk / bench_box2d / bench_box2d3 when the peers were built, with
# box2d3-version.txt naming the Box2D v3 tree it was built from); raw outputs
# and callgrind profiles are left there, never in git. Engines run
# interleaved (carom, chipmunk, box2d, box2d3, carom, ...) REPEATS times, so
# machine noise hits them alike; the tables show the median. Environment:
# BENCH_REPEATS (3).
set -eu

B=${1:-build/bench}
OUT=${2:-docs/performance.md}
REPEATS=${BENCH_REPEATS:-3}
RAW=$B/raw
mkdir -p "$RAW" "$(dirname "$OUT")"
: >"$RAW/compare.txt"
START=$(date +%s)

have () { [ -x "$B/$1" ]; }
if ! have bench_carom; then
  echo "run-bench: $B/bench_carom is missing (make bench-build)" >&2
  exit 1
fi
ENGINES="carom"
have bench_chipmunk && ENGINES="$ENGINES chipmunk"
have bench_box2d && ENGINES="$ENGINES box2d box2d-sleep"
have bench_box2d3 && ENGINES="$ENGINES box2d3"

# Steps per scene: a warm-up that is not timed, then the timed steps; the
# accuracy figures are read after both (10 s of simulated time).
scene_args () {
  case $1 in
  pyramid) echo "scene=pyramid warmup=60 steps=540" ;;
  rain) echo "scene=rain warmup=60 steps=540" ;;
  gas) echo "scene=gas warmup=60 steps=540" ;;
  chains) echo "scene=chains warmup=60 steps=540" ;;
  esac
}

# run ENGINE ARGS...: one bench line on stdout (only the key=value line)
run () {
  e=$1
  shift
  case $e in
  box2d-sleep) "$B/bench_box2d" "$@" sleep=1 | grep '^engine=' | sed 's/^engine=box2d /engine=box2d-sleep /' ;;
  *) "$B/bench_$e" "$@" | grep '^engine=' ;;
  esac
}

# key KEY LINE: the value of KEY in a key=value line
key () { printf '%s\n' "$2" | tr ' ' '\n' | sed -n "s/^$1=//p"; }

# median of the numbers on stdin
median () { sort -g | awk '{ v[NR] = $1 } END { if (NR) print v[int((NR + 1) / 2)]; else print "-" }'; }

echo "run-bench: engines: $ENGINES; $REPEATS rounds" >&2
LOAD_START=$(cut -d' ' -f1-3 /proc/loadavg)

# ------------------------------------------------------------ comparison
r=1
while [ "$r" -le "$REPEATS" ]; do
  for s in pyramid rain gas chains; do
    for e in $ENGINES; do
      # shellcheck disable=SC2046
      line=$(run "$e" $(scene_args "$s")) || line=""
      [ -n "$line" ] && printf 'round=%s %s\n' "$r" "$line" >>"$RAW/compare.txt"
      echo "  $line" >&2
    done
  done
  r=$((r + 1))
done

# lines of one engine and scene
pick () { grep " engine=$1 scene=$2 " "$RAW/compare.txt" || true; }
med_ms () { pick "$1" "$2" | while read -r l; do key ms_per_step "$l"; done | median; }
first () { pick "$1" "$2" | head -n 1; }
# carom / Box2D v3 in the scaling runs: scale_ratio SCENE BODIES
scale_ratio () {
  sc=$(grep "^engine=carom scene=$1 bodies=$2 " "$RAW/scaling.txt" | head -n 1 || true)
  sb=$(grep "^engine=box2d3 scene=$1 bodies=$2 " "$RAW/scaling.txt" | head -n 1 || true)
  if [ -n "$sc" ] && [ -n "$sb" ]; then
    awk -v m="$(key ms_per_step "$sc")" -v b="$(key ms_per_step "$sb")" 'BEGIN { printf "%.2f", m / b }'
  else
    echo "-"
  fi
}

# ------------------------------------------------------------ carom settings
: >"$RAW/settings.txt"
CONFIGS="1,1 2,1 4,1 4,2 8,1 8,2"
r=1
while [ "$r" -le "$REPEATS" ]; do
  for s in pyramid rain gas chains; do
    for cfg in $CONFIGS; do
      # shellcheck disable=SC2046
      run carom $(scene_args "$s") substeps="${cfg%,*}" iterations="${cfg#*,}" >>"$RAW/settings.txt" || true
    done
  done
  r=$((r + 1))
done
echo "run-bench: settings sweep done" >&2

# ------------------------------------------------------------ scaling
# Steps are capped so the whole run stays within minutes; the same warm-up
# (60 steps: the lowest rows of the rain have landed) at every size. Box2D
# v3, when built, runs the same scene right after carom at each size.
: >"$RAW/scaling.txt"
SCALE_ENGINES="carom"
have bench_box2d3 && SCALE_ENGINES="carom box2d3"
for s in gas rain; do
  for n in 1000 10000 100000; do
    case $n in
    1000) st=240 ;;
    10000) st=120 ;;
    100000) st=60 ;;
    esac
    for e in $SCALE_ENGINES; do
      run "$e" scene=$s bodies=$n warmup=60 steps="$st" >>"$RAW/scaling.txt" || true
    done
  done
done
echo "run-bench: scaling done" >&2

# ------------------------------------------------------------ memory
: >"$RAW/memory.txt"
for s in pyramid rain gas chains; do
  # shellcheck disable=SC2046
  "$B/bench_carom" $(scene_args "$s") mode=mem | grep '^engine=' >>"$RAW/memory.txt" || true
done
for n in 10000 100000; do
  "$B/bench_carom" scene=gas bodies=$n warmup=0 steps=60 mode=mem | grep '^engine=' >>"$RAW/memory.txt" || true
done

# ------------------------------------------------------------ broad phase
: >"$RAW/broadphase.txt"
if have bench_broadphase; then
  "$B/bench_broadphase" 1000 3000 10000 30000 100000 >>"$RAW/broadphase.txt" || true
fi
echo "run-bench: memory and broad phase done" >&2

# ------------------------------------------------------------ profile
# callgrind counts instructions (Ir), not cycles: cache misses do not show.
# Only carom_world_update is counted (not building the scene).
PROFILE=no
if command -v valgrind >/dev/null 2>&1 && command -v callgrind_annotate >/dev/null 2>&1; then
  PROFILE=yes
  for s in pyramid rain chains; do
    case $s in
    pyramid) st=120 ;;
    rain) st=300 ;;
    chains) st=120 ;;
    esac
    valgrind -q --tool=callgrind --callgrind-out-file="$B/callgrind.$s.out" \
      --toggle-collect=carom_world_update "$B/bench_carom" scene="$s" warmup=0 steps="$st" >/dev/null 2>&1 || PROFILE=no
    callgrind_annotate --auto=no --threshold=100 --inclusive=yes "$B/callgrind.$s.out" >"$B/profile-$s-inclusive.txt" 2>/dev/null || PROFILE=no
    callgrind_annotate --auto=no --threshold=100 --inclusive=no "$B/callgrind.$s.out" >"$B/profile-$s-exclusive.txt" 2>/dev/null || PROFILE=no
    # the same steps in Box2D v3, for instructions per step side by side
    if [ -x "$B/bench_box2d3" ]; then
      valgrind -q --tool=callgrind --callgrind-out-file="$B/callgrind.box2d3.$s.out" \
        --toggle-collect=b2World_Step "$B/bench_box2d3" scene="$s" warmup=0 steps="$st" >/dev/null 2>&1 || true
      callgrind_annotate --auto=no --threshold=100 --inclusive=yes "$B/callgrind.box2d3.$s.out" \
        >"$B/profile-box2d3-$s-inclusive.txt" 2>/dev/null || true
    fi
  done
  echo "run-bench: profiles in $B/callgrind.*.out, $B/profile-*.txt" >&2
fi

# Percent of the total per function from a callgrind_annotate listing, as
# "percent function", largest first. A function's lines inlined from another
# file (vec2.h) are listed apart: exclusive costs (MODE sum) are added up;
# the inclusive cost of the function's own file already covers them (MODE
# max). Only the function table is read.
by_function () {
  awk -v mode="$2" '
    /PROGRAM TOTALS/ { gsub(",", "", $1); total = $1; next }
    /file:function/ { table = 1; next }
    table && /^[[:space:]]*$/ { exit }
    table && /^ *[0-9,]+ \( *[0-9.]+%\)  / {
      n = $1; gsub(",", "", n)
      f = $0; sub(/^ *[0-9,]+ \( *[0-9.]+%\)  /, "", f); sub(/ \[.*$/, "", f)
      sub(/^.*:/, "", f); sub(/@@.*/, "", f)
      if (f ~ /^(main|\(below main\)|__libc_start_main|__libc_start_call_main|0x[0-9a-f]+)$/) next
      if (mode == "max") { if (n + 0 > sum[f] + 0) sum[f] = n } else sum[f] += n
    }
    END { for (f in sum) if (total > 0) printf "%.1f %s\n", 100 * sum[f] / total, f }
  ' "$1" | sort -rg
}
# the instructions a callgrind run counted, and that over the steps in millions
total_ir () { [ -f "$1" ] && sed -n 's/^summary: *//p; s/^totals: *//p' "$1" | head -n 1; }
per_step () { awk -v a="$1" -v n="$2" 'BEGIN { if (a + 0 > 0) printf "%.2fM", a / n / 1e6; else print "-" }'; }
incl () { by_function "$1" max | awk -v f="$2" '$2 == f { print $1; found = 1 } END { if (!found) print "0.0" }'; }
# the inclusive percents of several functions added up (they must not call
# each other)
incl_sum () {
  f=$1
  shift
  t=0
  for g in "$@"; do t=$(awk -v a="$t" -v b="$(incl "$f" "$g")" 'BEGIN { print a + b }'); done
  echo "$t"
}
# instructions per step of a share (percent) of a run's total over n steps
share_per_step () { awk -v p="$1" -v a="$2" -v n="$3" 'BEGIN { if (a + 0 > 0) printf "%.0fk", p * a / 100 / n / 1000; else print "-" }'; }
excl () { by_function "$1" sum | awk -v f="$2" '$2 == f { print $1; found = 1 } END { if (!found) print "0.0" }'; }

# ------------------------------------------------------------ the report
ratio () { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b + 0 > 0) printf "%.2f", a / b; else print "-" }'; }
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
mhz=$(sed -n 's/^cpu MHz[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
ccv=$(${CC:-cc} --version | head -n 1)
cxxv=$(${CXX:-c++} --version 2>/dev/null | head -n 1 || echo "none")
pkgv () { dpkg-query -W -f='${Version}' "$1" 2>/dev/null || echo "not installed"; }
# Box2D v3: built from a source tree by mk/bench.mk, which records its commit
B3V=$(cat "$B/box2d3-version.txt" 2>/dev/null || true)
b3v () { v=$(key "$1" "$B3V"); echo "${v:-unknown}"; }
case " $ENGINES " in
*" box2d3 "*) HAVE_B3=yes ;;
*) HAVE_B3=no ;;
esac
if [ "$HAVE_B3" = yes ]; then
  B3_PEER="; Box2D v3 $(b3v version) built from source, commit \`$(b3v commit)\` ($(b3v date)) of github erincatto/box2d"
else
  B3_PEER="; Box2D v3 not built (\`make bench BOX2D3_DIR=...\`)"
fi
LOAD_END=$(cut -d' ' -f1-3 /proc/loadavg)
ELAPSED=$(($(date +%s) - START))

engine_name () {
  case $1 in
  carom) echo "carom" ;;
  chipmunk) echo "Chipmunk 7" ;;
  box2d) echo "Box2D 2.4" ;;
  box2d-sleep) echo "Box2D 2.4, sleep on" ;;
  box2d3) echo "Box2D v3" ;;
  esac
}

# One row per scene: carom's median ms/step, then each other engine's with
# carom / engine beside it.
summary_table () {
  h="| scene | carom ms/step |"
  d="|---|---:|"
  for e in $ENGINES; do
    [ "$e" = carom ] && continue
    h="$h $(engine_name "$e") ms/step | carom / $(engine_name "$e") |"
    d="$d---:|---:|"
  done
  echo "$h"
  echo "$d"
  for s in pyramid rain gas chains; do
    cm=$(med_ms carom "$s")
    row="| $s | $cm |"
    for e in $ENGINES; do
      [ "$e" = carom ] && continue
      m=$(med_ms "$e" "$s")
      row="$row $m | $(ratio "$cm" "$m") |"
    done
    echo "$row"
  done
}

scene_table () {
  s=$1
  cm=$(med_ms carom "$s")
  echo "| engine | settings | ms/step (median of $REPEATS) | all rounds | carom / engine | top drift | escaped | energy drift | contact points |"
  echo "|---|---|---:|---|---:|---:|---:|---:|---:|"
  for e in $ENGINES; do
    l=$(first "$e" "$s")
    [ -n "$l" ] || continue
    m=$(med_ms "$e" "$s")
    all=$(pick "$e" "$s" | while read -r x; do key ms_per_step "$x"; done | tr '\n' ' ' | sed 's/ $//')
    echo "| $(engine_name "$e") | $(key settings "$l" | tr ',' ' ') | $m | $all | $(ratio "$cm" "$m") | $(key top_drift "$l") | $(key escaped "$l") | $(key energy_drift "$l") | $(key contacts "$l") |"
  done
}

# The chains: ms/step and its cost per joint, and how far the joints came
# apart (joint gap: the mean distance between a joint's two anchors at the
# end, bench_joint_gap in bench/scenes.c).
joint_table () {
  s=$1
  cm=$(med_ms carom "$s")
  echo "| engine | settings | ms/step (median of $REPEATS) | all rounds | carom / engine | us per joint per step | mean joint gap | escaped | contact points |"
  echo "|---|---|---:|---|---:|---:|---:|---:|---:|"
  for e in $ENGINES; do
    l=$(first "$e" "$s")
    [ -n "$l" ] || continue
    m=$(med_ms "$e" "$s")
    all=$(pick "$e" "$s" | while read -r x; do key ms_per_step "$x"; done | tr '\n' ' ' | sed 's/ $//')
    echo "| $(engine_name "$e") | $(key settings "$l" | tr ',' ' ') | $m | $all | $(ratio "$cm" "$m") | $(per_joint_us "$m" "$(key joints "$l")") | $(key joint_gap "$l") | $(key escaped "$l") | $(key contacts "$l") |"
  done
}
per_joint_us () { awk -v m="$1" -v n="$2" 'BEGIN { if (m + 0 > 0 && n + 0 > 0) printf "%.3f", 1000 * m / n; else print "-" }'; }
per_joint_ir () { awk -v a="$1" -v st="$2" -v n="$3" 'BEGIN { if (a + 0 > 0 && n + 0 > 0) printf "%.0f", a / st / n; else print "-" }'; }
CHAIN_JOINTS=$(key joints "$(first carom chains)")
CHAIN_ST=120
# the joints' own stages in carom (lib/solver.c calls them), inclusive
JOINT_STAGES="joint_prepare joint_mark_bodies gravity_joint_hold joint_warm_start joint_solve joint_project gravity_joint_kick joint_sum_reaction joint_finish"
joint_share () { for f in $JOINT_STAGES; do incl "$1" "$f"; done | awk '{ t += $1 } END { printf "%.1f", t }'; }

# Cost per joint, carom beside Box2D v3: time, and instructions when the
# profile ran.
per_joint_table () {
  echo "| engine | ms/step | us per joint per step | instructions per step | instructions per joint per step |"
  echo "|---|---:|---:|---:|---:|"
  for e in carom box2d3; do
    case " $ENGINES " in *" $e "*) ;; *) continue ;; esac
    m=$(med_ms "$e" chains)
    if [ "$e" = carom ]; then f=$B/callgrind.chains.out; else f=$B/callgrind.box2d3.chains.out; fi
    ir=""
    [ "$PROFILE" = yes ] && ir=$(total_ir "$f")
    echo "| $(engine_name "$e") | $m | $(per_joint_us "$m" "$CHAIN_JOINTS") | $(per_step "$ir" "$CHAIN_ST") | $(per_joint_ir "$ir" "$CHAIN_ST" "$CHAIN_JOINTS") |"
  done
}

{
  cat <<EOF
# carom performance

Generated by \`make BUILD=$(dirname "$B") bench\` (bench/run-bench.sh) on $(date -u '+%Y-%m-%d %H:%M UTC'),
in ${ELAPSED} s. Do not edit by hand: run it again.

Machine: $(nproc) cores, $cpu (${mhz} MHz), load average $LOAD_START at the start and
$LOAD_END at the end (other work shares this machine; every figure is single
threaded). Compilers: $ccv; $cxxv. Peers: libchipmunk-dev $(pkgv libchipmunk-dev),
libbox2d-dev $(pkgv libbox2d-dev) (Debian packages)${B3_PEER}.

## How it is measured

* One scene generator (bench/scenes.c) gives every engine the same bodies:
  shape, size, pose, velocity, density 1, and the same joints. The four scenes:
  * **pyramid**: 20 rows of 1 x 1 boxes (210) on a static ground box, gravity -10,
    friction 0.6, restitution 0.
  * **rain**: 2000 polygons (boxes, triangles, pentagons, hexagons, size 0.5 to 1,
    random angle) on a jittered grid, falling into an open-top static container
    about 67 units wide, gravity -10, friction 0.6, restitution 0.
  * **gas**: 500 such polygons on a jittered grid (not touching) with random
    velocities \|v\| <= 5 in a closed box of static walls, no gravity,
    restitution 1, friction 0.
  * **chains**: 25 chains of 40 links (0.25 x 0.05 boxes, 1000 bodies) on revolute
    joints at their ends, the first link's to a fixed point (1000 joints), each
    laid straight at 45 degrees below the horizontal and let go, on a grid 24
    apart so that no two chains meet (links of one chain may), gravity -10,
    friction 0.6. Every engine's revolute joint at its defaults, joined bodies
    not colliding (Box2D v3: soft joints, constraint hertz 60, damping ratio 2;
    Chipmunk: pivot joints).
* dt = 1/60, 60 warm-up steps, then 540 timed steps;
  \`clock_gettime(CLOCK_MONOTONIC)\` around the step calls only. The accuracy
  figures are read after all 600 steps (10 s):
  * **top drift**: how far the pyramid's top box moved from its start, over its size;
  * **escaped**: bodies whose centre ended outside the container (tunnelled or thrown out);
  * **energy drift**: kinetic energy at the end over the start, minus 1 (gas; e = 1
    should keep it near 0);
  * **contact points**: touching points at the end, as each engine counts them;
  * **mean joint gap** (chains): the distance between a joint's two anchors at
    the end, averaged over the joints: the points of its two bodies that were at
    the joint at the start, carried with the bodies (the same code for every
    engine, bench_joint_gap in bench/scenes.c); the links are 0.25 long.
* Rounds: the engines run interleaved ($ENGINES), $REPEATS rounds; the
  table gives the median, then every round. **carom / engine** > 1 means carom is slower.
* Two builds of carom are compared in time by \`tools/compare-bench A B PAIRS
  [options]\`: A and B run in pairs whose order alternates, and it prints
  the median of B's time over A's, for all pairs and for each order apart.
  On this machine the second of two runs in a row is often a few percent
  faster or slower than the first, so pairs timed in one order measure that
  as well.
* Build: every bench is compiled by the same compiler with \`-O2 -g\` (\`\$(OPT)\`);
  C with \`-std=c99\` (the Box2D v3 bench with \`-std=c11\`, which its headers need),
  the Box2D 2.4 bench with \`-std=c++17\`. carom is linked statically from this tree,
  its library built as the Makefile builds it (\`-O3 -g\`, \`\$(LIB_OPT)\`);
  Chipmunk and Box2D 2.4 are Debian's shared libraries as packaged (their own
  flags). Debian's Chipmunk is built **without NDEBUG** (it prints "Debug Enabled":
  its runtime assertions are on), which costs it some speed. Box2D v3 is built
  from its source tree by its own CMake in Release (\`-O3 -DNDEBUG\`, its default
  SSE2 code, AVX2 off) and linked statically. carom's batch kernels are
  those of the best path the CPU has (AVX-512's registers on this one; the
  same bits on every path, docs/reliability.md).
* Settings: carom with its defaults (substeps 4, iterations 1, continuous
  collision on; other settings below). Chipmunk: iterations 10, collision slop 0.01 (its default 0.1 is meant
  for pixel-sized bodies), no sleeping (its default), bounding-box tree. Box2D:
  velocity iterations 8, position iterations 3, continuous collision on (its
  default), sleeping **off** so that every engine steps every body every step;
  the extra row "sleep on" is Box2D's own default. Box2D's restitution threshold
  (1 m/s) is set to 0 in the gas, where there is no gravity, as carom does.
  Box2D v3: its defaults (4 sub-steps per step, contact hertz 30, damping
  ratio 10, continuous collision on), one worker and no task system (single
  threaded), sleeping **off** as for Box2D 2.4, restitution threshold 0 in the gas.
  Friction and restitution are given per shape so that each engine's mixing
  rule yields the scene's mu and e (Chipmunk multiplies: sqrt(mu) per shape).
  Box2D (2.4 and v3) computes in float, carom and Chipmunk in double.
* Box2D v3's contact points include its speculative points (manifold points up
  to 4 linear slops, 0.02, apart, not yet touching), so its counts run higher
  where bodies rest near one another (the rain).
* In the rain, Box2D 2.4 spends about half its time in continuous collision
  (b2World::SolveTOI, by \`perf\`), work that Box2D v3 no longer does this way;
  sleeping barely helps it there in 10 s because the pile keeps settling.

## Summary

Median ms/step of each engine and carom / engine (> 1: carom is slower); the
tables below give every round and the accuracy figures.

$(summary_table)

## Pyramid (210 boxes)

$(scene_table pyramid)

## Rain (2000 polygons)

$(scene_table rain)

## Gas (500 polygons, e = 1)

$(scene_table gas)

## Chains (1000 links, 1000 revolute joints)

$(joint_table chains)

Cost per joint, carom beside Box2D v3: the median ms/step above over the
$CHAIN_JOINTS joints, and the instructions callgrind counted in the step calls
(\`carom_world_update\`, \`b2World_Step\`) over the first $CHAIN_ST steps from the
start$(if [ "$PROFILE" = yes ]; then echo ""; else echo " (valgrind was missing: no instruction counts)"; fi).

$(per_joint_table)

Targets (Box2D v3 / Chipmunk 7, measured by others on this machine): pyramid
0.15 / 0.39 ms, rain 1.3 / 3.6 ms, gas 0.29 / 0.16 ms. $(if [ "$HAVE_B3" = yes ]; then
  echo "Box2D v3 in this run (commit \`$(b3v commit)\`): pyramid $(med_ms box2d3 pyramid), rain $(med_ms box2d3 rain), gas $(med_ms box2d3 gas) ms."
else
  echo "Box2D v3 is not packaged for Debian 12 and was not built for this run (\`BOX2D3_DIR\`), so Box2D 2.4 stands in for it here."
fi)

## carom settings tried

Median of $REPEATS rounds, the settings interleaved within each scene (not with
the other engines, so compare with the carom row above with care). The defaults
are substeps 4, iterations 1.

| substeps | iterations | pyramid ms/step | pyramid top drift | rain ms/step | rain escaped | gas ms/step | gas energy drift | chains ms/step | chains mean joint gap |
|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|
EOF
  for cfg in $CONFIGS; do
    sel () { grep " scene=$1 " "$RAW/settings.txt" | grep "settings=substeps=${cfg%,*},iterations=${cfg#*,}\$" || true; }
    sms () { sel "$1" | while read -r l; do key ms_per_step "$l"; done | median; }
    p=$(sel pyramid | head -n 1)
    ra=$(sel rain | head -n 1)
    g=$(sel gas | head -n 1)
    ch=$(sel chains | head -n 1)
    echo "| ${cfg%,*} | ${cfg#*,} | $(sms pyramid) | $(key top_drift "$p") | $(sms rain) | $(key escaped "$ra") | $(sms gas) | $(key energy_drift "$g") | $(sms chains) | $(key joint_gap "$ch") |"
  done
  cat <<EOF

## Scaling

Warm-up 60 steps, then the timed steps; steps are capped at large sizes to keep
\`make bench\` within minutes (1k: 240, 10k: 120, 100k: 60 timed steps). The rain
is then early in its fall (the lowest rows have landed, most bodies are in free
fall), more so in the bigger scenes (more rows above), so compare per-body costs
with the contact counts in mind. Box2D v3 (its defaults, as in the tables above)
runs each scene right after carom, once: one round, not the median of three.

| scene | bodies | timed steps | carom ms/step | us per body per step | contact points at the end | Box2D v3 ms/step | carom / Box2D v3 | Box2D v3 contact points |
|---|---:|---:|---:|---:|---:|---:|---:|---:|
EOF
  grep '^engine=carom ' "$RAW/scaling.txt" | while read -r l; do
    s=$(key scene "$l")
    n=$(key bodies "$l")
    m=$(key ms_per_step "$l")
    b=$(grep "^engine=box2d3 scene=$s bodies=$n " "$RAW/scaling.txt" | head -n 1 || true)
    if [ -n "$b" ]; then
      bm=$(key ms_per_step "$b")
      peer="$bm | $(awk -v m="$m" -v b="$bm" 'BEGIN { printf "%.2f", m / b }') | $(key contacts "$b")"
    else
      peer="- | - | -"
    fi
    echo "| $s | $n | $(key steps "$l") | $m | $(awk -v m="$m" -v n="$n" 'BEGIN { printf "%.3f", 1000 * m / n }') | $(key contacts "$l") | $peer |"
  done
  cat <<EOF

## Memory (carom)

Counted by a counting allocator (carom_world_def.allocator): live bytes after
building the scene, and after the warm-up and timed steps. Bytes per body: the
built world less an empty one, per body (statics included). Broad phase: measured
apart, on a copy of the scene with every body static. Bytes per contact point: the
stepped world less the built world and its broad phase, over the contact points at
the end. Arrays grow by doubling and the contacts are double buffered (this and
last step's, for warm starting), so these are bytes held, not bytes used.
The chains' bytes per body hold their joints too (one joint per link).

| scene | bodies | steps | bytes per body | broad phase bytes per body | contact points | bytes per contact point | peak bytes |
|---|---:|---:|---:|---:|---:|---:|---:|
EOF
  while read -r l; do
    echo "| $(key scene "$l") | $(key bodies "$l") | $(key steps "$l") | $(key bytes_per_body "$l") | $(key broadphase_bytes_per_body "$l") | $(key contacts "$l") | $(key bytes_per_contact "$l") | $(key peak_bytes "$l") |"
  done <"$RAW/memory.txt"
  cat <<EOF

## Broad phase (carom_world_detect alone)

n boxes of size 0.5 to 1 at uniformly random positions, at the rain's density
(one body per 1.5 x 1.5 cell), no motion: the time of the first detection (full
sort) and the median of 7 later ones, each after every body moved by up to 0.02
(the incremental path). Detection includes the narrow phase on the pairs found.
A flat per-body cost means O(n) or O(n log n); a per-body cost growing like
sqrt(n) means the single-axis sweep tests a whole strip of the world per body.

| bodies | contact points | first ms | first ns/body | moved ms | moved ns/body |
|---:|---:|---:|---:|---:|---:|
EOF
  while read -r l; do
    echo "| $(key bodies "$l") | $(key contacts "$l") | $(key first_ms "$l") | $(key first_ns_per_body "$l") | $(key moved_ms "$l") | $(key moved_ns_per_body "$l") |"
  done <"$RAW/broadphase.txt"
  awk '
    { for (i = 1; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] } n[NR] = v["bodies"]; c[NR] = v["moved_ns_per_body"] }
    END {
      if (NR >= 2 && c[1] > 0) {
        g = c[NR] / c[1]; s = sqrt(n[NR] / n[1]); l = log(n[NR]) / log(n[1])
        printf "\nFrom %d to %d bodies the per-body cost of the moved detection grew %.1fx\n", n[1], n[NR], g
        printf "(O(n log n) would give %.1fx, O(n sqrt n) %.1fx).\n", l, s
      }
    }' "$RAW/broadphase.txt"
  if [ "$PROFILE" = yes ]; then
    cat <<EOF

## Profile (callgrind, instructions)

\`valgrind --tool=callgrind --toggle-collect=carom_world_update\` on bench_carom:
pyramid for 120 steps, rain (2000) for 300 steps, chains for $CHAIN_ST steps from the start. Percentages are
of the instructions executed inside carom_world_update; static functions inlined
by the compiler count in their caller (drift and substep in carom_world_update). The
broad phase's own share is broadphase_update's less the narrow phase it calls
(on_pair). Instruction counts do not show cache misses; valgrind runs no
AVX-512 code, so the batch kernels counted are the AVX2 ones (the same
bits; more instructions than the AVX-512 ones, which take eight lanes at
once). Raw profiles:
\`$B/callgrind.*.out\` and \`$B/profile-*.txt\` (not in git).

EOF
    for s in pyramid rain chains; do
      inc=$B/profile-$s-inclusive.txt
      exc=$B/profile-$s-exclusive.txt
      det=$(incl "$inc" contacts_update)
      nar=$(incl "$inc" on_pair)
      # the broad phase's own: all of broadphase_update but the pairs' narrow phase
      bro=$(awk -v a="$(incl "$inc" broadphase_update)" -v b="$nar" 'BEGIN { printf "%.1f", a - b }')
      sol=$(incl "$inc" solver_step)
      echo "### $s"
      echo
      st=120; [ "$s" = rain ] && st=300; [ "$s" = chains ] && st=$CHAIN_ST
      ir_c=$(total_ir "$B/callgrind.$s.out")
      ir_b=$(total_ir "$B/callgrind.box2d3.$s.out")
      if [ -n "$ir_b" ]; then
        echo "Instructions per step: carom $(per_step "$ir_c" "$st"), Box2D v3 $(per_step "$ir_b" "$st") (b2World_Step counted the same way), carom / Box2D v3 $(ratio "$ir_c" "$ir_b")."
      else
        echo "Instructions per step: carom $(per_step "$ir_c" "$st") (Box2D v3 not built for this run)."
      fi
      echo
      echo "Stages: detection $det% (of which the broad phase's own sweep and sort $bro%, the narrow phase and contact matching $nar%), solver $sol%, the rest (integration, gravity, bookkeeping) $(awk -v a="$det" -v b="$sol" 'BEGIN { printf "%.1f", 100 - a - b }')%."
      if [ -n "$ir_b" ] && [ "$s" != chains ] && [ -f "$B/profile-box2d3-$s-inclusive.txt" ]; then
        b3p=$B/profile-box2d3-$s-inclusive.txt
        c_det=$det
        c_set=$(incl_sum "$inc" contact_prepare contact_batch_prepare contact_shock_prepare)
        c_pas=$(incl_sum "$inc" contact_batch_warm_start contact_batch_solve contact_batch_solve_push_out contact_batch_push_out contact_warm_start contact_solve contact_push_out contact_shock contact_restitution contact_batch_store)
        b_det=$(incl_sum "$b3p" b2CollideTask b2UpdateBroadPhasePairs)
        b_set=$(incl_sum "$b3p" b2PrepareContactsTask)
        b_pas=$(incl_sum "$b3p" b2WarmStartContactsTask b2SolveContactsTask b2ApplyRestitutionTask b2StoreImpulsesTask)
        echo
        echo "Instructions per step by stage, carom beside Box2D v3 (inclusive counts of each engine's functions for the stage: carom's contacts_update; contact_prepare, contact_batch_prepare and contact_shock_prepare; the contact passes of contact_batch.c, contact_solver.c, shock.c and impact.c's contact_restitution. Box2D v3's b2CollideTask and b2UpdateBroadPhasePairs; b2PrepareContactsTask; b2WarmStartContactsTask, b2SolveContactsTask, b2ApplyRestitutionTask and b2StoreImpulsesTask):"
        echo
        echo "| stage | carom | Box2D v3 | carom / Box2D v3 |"
        echo "|---|---:|---:|---:|"
        for row in "detection (broad and narrow phase) $c_det $b_det" "contact set-up $c_set $b_set" "contact passes (warm start, solve, relax, push-out, restitution) $c_pas $b_pas"; do
          name=${row% * *}
          pc=$(echo "$row" | awk '{ print $(NF - 1) }')
          pb=$(echo "$row" | awk '{ print $NF }')
          echo "| $name | $(share_per_step "$pc" "$ir_c" "$st") | $(share_per_step "$pb" "$ir_b" "$st") | $(ratio "$(awk -v p="$pc" -v a="$ir_c" 'BEGIN { print p * a }')" "$(awk -v p="$pb" -v a="$ir_b" 'BEGIN { print p * a }')") |"
        done
        rc_=$(awk -v a="$c_det" -v b="$c_set" -v c="$c_pas" 'BEGIN { print 100 - a - b - c }')
        rb_=$(awk -v a="$b_det" -v b="$b_set" -v c="$b_pas" 'BEGIN { print 100 - a - b - c }')
        echo "| the rest (integration, gravity, bookkeeping) | $(share_per_step "$rc_" "$ir_c" "$st") | $(share_per_step "$rb_" "$ir_b" "$st") | $(ratio "$(awk -v p="$rc_" -v a="$ir_c" 'BEGIN { print p * a }')" "$(awk -v p="$rb_" -v a="$ir_b" 'BEGIN { print p * a }')") |"
      fi
      if [ "$s" = chains ]; then
        echo
        echo "Of the solver, the joints' stages (lib/solver.c's joint_* and gravity_joint_* calls) take $(joint_share "$inc")%: the velocity passes (joint_solve, the solve and relax passes of each sub-step) $(incl "$inc" joint_solve)%, the position projections after each sub-step's move (joint_project) $(incl "$inc" joint_project)%; both run the direct solve of the joint trees (lib/joint_tree.c), whose functions lead the table below."
      fi
      echo
      echo "| function | inclusive % | exclusive % |"
      echo "|---|---:|---:|"
      by_function "$exc" sum | head -n 14 | while read -r p f; do
        echo "| $f | $(incl "$inc" "$f") | $p |"
      done
      echo
    done
  fi
  echo "## Where carom is slower, and what is planned"
  echo
  if [ "$HAVE_B3" = yes ]; then
    cat <<EOF
The targets were Box2D v3 at 0.15 ms for the pyramid, 1.3 ms for the rain and
0.29 ms for the gas, and Chipmunk 7 at 0.39 / 3.6 / 0.16 ms, measured by others
on this machine. Box2D v3 ran here too (commit \`$(b3v commit)\`): carom / Box2D v3
is $(ratio "$(med_ms carom pyramid)" "$(med_ms box2d3 pyramid)") on the pyramid, $(ratio "$(med_ms carom rain)" "$(med_ms box2d3 rain)") on the rain and $(ratio "$(med_ms carom gas)" "$(med_ms box2d3 gas)") on the gas
(> 1: carom is slower; the other engines are in the summary above). At 10k
and 100k bodies (the scaling table, one round) it is $(scale_ratio rain 10000) and $(scale_ratio rain 100000)
on the rain, $(scale_ratio gas 10000) and $(scale_ratio gas 100000) on the gas. Where carom is
behind, the profile above shows why:
EOF
  else
    cat <<'EOF'
The targets were Box2D v3 (not built for this run: see BOX2D3_DIR in
mk/bench.mk) at 0.15 ms for the pyramid, 1.3 ms for the rain and 0.29 ms for
the gas, and Chipmunk 7 at 0.39 / 3.6 / 0.16 ms, measured by others on this
machine. Against the engines measured in this run, carom is fastest on the gas
(where it is also the one that keeps its energy, docs/accuracy.md) and on the
rain, and level with Chipmunk on the pyramid (within a few percent either way
from run to run on this shared machine: compare the rounds). Against Box2D v3's
figures it is behind on the pyramid (about 1.5x) and the rain (about 2x), for
reasons the profile above shows:
EOF
  fi
  cat <<'EOF'

- **The contact passes** (warm start, solve, relax, push-out, restitution
  and shock propagation: the stage tables above) take about as many
  instructions per step as Box2D v3's. The contact graph is coloured and
  each colour packed into batches of eight contacts, solved in double
  precision: a batch at once with AVX-512's registers where the CPU has
  them, as this one does (lib/contact_batch_avx512.c: eight doubles a
  register, 32 registers, masks in mask registers), four contacts at a
  time with AVX2 (lib/contact_batch_avx2.c) or the portable kernels
  (lib/contact_batch.c), each walking a batch in two groups of four; the
  same bits on every path. Against batches of four, solved four at a
  time on every path (`tools/compare-bench`, `warmup=60 steps=540`):
  the AVX-512 kernels take 0.954 of the time on the pyramid (16 pairs;
  fastest runs 0.1113 and 0.1062 ms) and 0.999 on the rain (16 pairs;
  the settled rain, `warmup=450 steps=600`, 0.996 over 10: there the
  passes wait on memory, not on arithmetic); the AVX2 kernels 1.003 on
  the pyramid (12 pairs of `warmup=60 steps=3000`, a build choosing its
  path by hand), the same instructions to 0.1% (callgrind, 229.3M and
  229.1M over 120 steps); the portable kernels, their lane operations now
  always inlined, 0.792 (8 pairs of `steps=1000`). Eight lanes in two
  AVX2 registers each were measured before and not taken: they spilled
  more (607 of 1464 instructions of the solve pass on the stack) and took
  4.5% and 5.6% more time. The passes do what Box2D v3's do
  not: the exact 2x2 solve of two-point faces, a push-out on separate pseudo-velocities (split
  impulses, so position correction adds no energy; its first pass of a
  sub-step rides in the same walk over the batches as the last solve pass,
  so the batches are walked three times a sub-step, as Box2D v3 walks its
  constraints), and shock propagation under a heavy body resting on a
  light one and along columns (in the rain, whose polygons pile on each
  other, the pass takes about a tenth of the step: docs/physics.md).
  Box2D v3 solves in float, four lanes in the SSE2 build
  measured here (eight with AVX2).
- **Set-up and detection** are where carom executes more. Every step,
  every contact's lever arms, effective masses, 2x2 matrix, time-of-impact
  test and gravity-drift flags are computed again and packed into its
  batch lane (contact_prepare, contact_batch_prepare), and every pair's
  points are moved with the bodies from where they were computed (or
  computed again, beyond `manifold_tolerance`: from its second second on,
  the pyramid keeps 99.98% of its manifolds; docs/accuracy.md measures the
  knob). The SAT test searches a piece's nearest vertex only along the
  edges that can be the most separating (those within the other piece's
  bounding radius of the largest gap to its vertex average), which cut
  the rain's instructions in that search by a quarter (callgrind, 240 steps:
  614M to 466M) with the same results to the bit. Matching with last
  step's contacts tries the one after the last match, and a hash only when
  that fails; a reused manifold's points are written straight into the
  new contact, each point's copy on the far body kept in that body's frame.
  The set-up loads each contact's body values once for its points and
  skips the time-of-impact test at its first resting point; the colouring
  walks the contacts once; the sweep's windows end at a sentinel. Those,
  and building the library at -O3, took 13.3% off the pyramid's
  instructions, 12.7% off the rain's and 11.9% off the gas's with the same
  results to the bit (callgrind as in the profile above, pyramid 120
  steps, rain and gas 300, continuous collision off: 182.5M to 158.2M,
  4218.9M to 3681.4M, 301.1M to 265.2M). Continuous collision, on by
  default since, took them to 159.1M, 3885.4M and 338.0M (the gas's bodies
  now meet at their time, docs/effects.md); shock propagation computing a
  row's gaps once for the two passes that see the same positions and
  solving rows by their kind, the pruned SAT search inline, the set-up's
  masses tested once, the events' table kept between updates and the
  rotations and boxes two lanes at a time brought them to 155.8M, 3623.2M
  and 322.4M, again to the bit. A time-of-impact search from the start of
  the step takes the detection's own SAT measure of the pieces (their
  separation and its face) instead of measuring them again, to the bit:
  the gas 293.4M to 289.6M, the rain 3700.2M to 3677.7M (300 steps). A
  pair's margins (the speculative one, three square roots with continuous
  collision, and the kept one) are computed only when a narrow phase or a
  bounding-circle test beyond the pieces' radii needs them, which a pair
  whose manifold is reused does not: the pyramid 157.05M to 152.72M (120
  steps), the settled rain 855.3M to 835.7M (steps 451 to 510), again to
  the bit; `tools/compare-bench` gave 0.958 on the pyramid. Sampled in
  time, a quarter of the pyramid's detect_pair waited on three square
  roots a pair: the distance of the pieces' centres, that of the pair's
  motion since its manifold was computed, and the mix of two frictions.
  The first two are now compared squared where that decides
  (vec2.h's v2_len_surely_within, tested against the root to the last
  place), the root taken only within a rounding of the bound, and two
  equal frictions mix to themselves (the root of a square is exact): to
  the bit, the pyramid 152.81M to 152.34M instructions (120 steps), but
  `tools/compare-bench` 0.975 (16 pairs; the fastest runs 0.1179 and
  0.1170 ms): a root's latency, not its instruction, is what the pair
  waited on. Contacts that keep their set-up while they persist, redoing
  only what moved, are what is planned next: the set-up's time is in
  what it reads and writes, not in its arithmetic. Measured and not
  kept: the batched contacts set up eight at a time, each gathered into
  lanes in list order, the arithmetic in the batch kernels' operations
  (square root and division too) and written back, with the same bits
  (the pyramid's lanes all taken, 87% of the rain's, the rest one at a
  time). The pyramid's instructions fell 4.9% (callgrind, 120 steps,
  156.1M to 148.4M), but in time (`tools/compare-bench`) it took 1.023
  of the pyramid's and 1.019 of the rain's, and with the lanes written
  from the kernel's arrays instead of packed from the contacts 0.958 and
  1.063: `perf` gave the kernel 3.3% of the pyramid's samples and the
  gathering and writing back 19.5%, the loads of the bodies and the
  stores into the contacts' points the slowest. Asking the memory for
  the contact four on and its bodies (software prefetch) gave 0.985 and
  1.035.
  Box2D v3 keeps a manifold while the pair moved less than 5 cm plus its
  extent times the sine of the turn, and turned less than 11 degrees;
  carom's default keeps it within 1% of the smaller body's size and 0.01
  rad. A default of 5% took 11.5% off the settled rain's instructions
  (callgrind, steps 200 to 260), but a box tipping over from its corner
  then landed its far corner deeper than with no reuse at all: the
  default is what tests/test_manifold_reuse.c's tipping boxes allow.
- **Time per instruction.** carom's records are double precision: a
  contact is 216 bytes and each of its points 280, a batch lane 408 with
  two points and 208 with one, a solver body 128. Where the contacts
  outgrow the caches (the rain's 6000 points), carom's ratio to Box2D v3
  in time is above its ratio in instructions (the summary against the
  instructions per step above), and what the passes stream counts: a
  batch of one-point lanes (two thirds of the settled rain's) ends before
  the second point and the 2x2 problem it never reads, and a shock row
  holds the points its contact has (an 80-byte row and 96 bytes a point,
  not 456 bytes for every row). Those two took the settled rain's time
  down by about 2%, with the same bits: `tools/compare-bench` (two
  builds, runs in pairs whose order alternates, `scene=rain warmup=450
  steps=100`) gave a median ratio of 0.984 and 0.977 in two runs of 20
  pairs, the fastest runs 1.94 and 1.89 ms, 1.97 and 1.91. (Timed always
  in the same order the two builds had given 0.933: on this machine the
  second of two runs in a row is often a few percent faster or slower
  than the first, in either direction from one run of pairs to the next.)
  Cachegrind with a 2 MB last level (`--LL=2097152,16,64`, `warmup=0
  steps=300`) counted 28.4M read misses there before, 25.2M after.
  Sampled in time (`perf record` on `bench_carom scene=rain warmup=450
  steps=1500`, the rain settled after its first 450 steps), detect_pair
  took 14% of the samples, where it executes 11% of the instructions
  (callgrind, `warmup=450 steps=100`, with what the compiler inlined
  into it): the kept pairs come in the order of
  the bodies' boxes, not of their slots, and each pair's detection waited
  for both bodies' first cache lines and their convex pieces, its slowest
  instructions the loads of a body's shape and of a piece's centre. In
  worlds of 1024 bodies or more the broad phase now asks the memory for
  the bodies of the pair four places on and for their pieces two places
  on before it reports a pair (lib/broadphase.c, report_kept), with the
  same results to the bit: detect_pair 8.6% of the samples after, the
  reporting loop 4.6%; `tools/compare-bench` (20 pairs, `scene=rain
  warmup=450 steps=100`) 0.969 and 0.989 in two runs, the fastest runs
  1.90 and 1.86 ms, 1.88 and 1.85. Smaller worlds keep their bodies in
  the caches from one step to the next: the pyramid asks for nothing (its
  instructions 388.01M before and 388.62M after over 300 steps, the rise
  the copying of the pairs' slots; asking there too, 394.2M). The
  batches' own size is not what the passes wait on: the settled rain's
  batches take 1.03 MB (943 of them, 624 of one-point lanes), about this
  processor's second-level cache, yet batches made 128 bytes larger by a
  padding (12% more bytes) timed the same (`tools/compare-bench`, 16
  pairs: 1.006, the fastest runs 2.063 and 2.067 ms): the passes read
  them in order, which the processor fetches ahead. Where they lie in the
  lines is: the batches' arrays of eight doubles began 104 bytes into a
  batch that began wherever the allocator's block did, so most of the
  AVX-512 kernels' loads and stores spanned two cache lines, and the
  solver bodies' rows (AVX2 and AVX-512 gathers) did too. Each array now
  fills a line of its own (the batch's indices padded to two lines, the
  batches and solver bodies from a line on, lib/alloc.c's
  mem_reserve_lines; shock propagation's four-lane arrays half a line),
  with the same bits. `tools/compare-bench` against the build before
  varied from run to run more than it gained: the rain (`warmup=60
  steps=540`) 0.967, 0.866 and 0.991 in three runs of 16 to 20 pairs,
  the settled rain (`warmup=450 steps=600`) 0.898 and 0.996, the pyramid
  0.977 (`steps=3000`); with the AVX2 kernels (scratch builds that pass
  over AVX-512) the rain 0.931, the settled rain 0.986, the pyramid
  0.988. Every rain run's fastest was faster, by 2% to 8% (1.725 ms to
  1.661, 1.621 to 1.566; AVX2 1.917 to 1.856). Cachegrind, which runs
  the AVX2 kernels and counts a load that spans two lines as one, saw
  the same instructions and 0.5% fewer misses at a last level of 1 MB.
  The bodies padded to six lines and placed from a line on, so that
  detection's first four lines of a body are four and not five, timed
  the same (the settled rain 1.001, the gas 1.004): not kept.
  Branches that the data decide cost as much: cachegrind's branch
  simulation (`valgrind --tool=cachegrind --branch-sim=yes` on
  `bench_carom scene=rain warmup=0 steps=300`) counted 88k mispredicted
  branches a rain step before the broad phase's window test, SAT's running
  best, a rotation's quadrant, the search for a free colour and the warm
  start's rescaling were made branch-free, and 57k after. Some of those
  selects the compiler had turned back into jumps (a rotation's quadrant,
  the warm start's rescaling: objdump); they are now masks (vec2.h's
  select_double), and which of a pair's bodies comes first and the kept
  pairs' box test are chosen without a jump too: 48.8k a step, 59.0k
  before, in the same count. A batch of
  one-point contacts solves one point, not two (contact_batch.points);
  small functions of the per-contact loops whose vector arguments went
  through the stack (a store-forwarding stall at every call) are inlined.
  Counted over the same steps (callgrind started after the warm-up, a
  scratch copy of each bench), carom executes 1.35 times Box2D v3's
  instructions while the rain lands (steps 181 to 240: 1116M against
  828M) and 1.21 times once it has settled (steps 451 to 510: 834M against
  690M), but takes about 2.2 and 1.9 times its time: per instruction it
  is 1.6 times slower. Tried for that and not kept, each with the same
  bits: the set-up's four divisions a point as two two-lane divisions
  (1.5% more instructions, no change in time: the divisions are not what
  it waits on); asking for each contact and its points six places ahead
  of the packing, which visits them in colour order (no change); the
  shock rows ordered in waves, each row after every earlier one that
  shares a body it moves (1807 rows in 28 waves in the settled rain), so
  that the rows next to each other do not wait on each other, with and
  without a branch-free row (no change, and 8% slower without branches);
  a point's fields ordered so that a reused manifold reads two of last
  step's point's five cache lines (the simulated last level's read misses
  9.5% fewer, yet 3% to 6% slower in time); and, at 10k bodies, asking
  for each body's vertices four bodies ahead of its box (no change).
  Where the time per instruction goes, counted: callgrind's cache
  simulation (`--cache-sim=yes --D1=32768,8,64 --LL=2097152,16,64`,
  started after the warm-up in the scratch copies of both benches, the
  settled rain's steps 451 to 510) gives carom 9.40M read misses and
  5.53M write misses at the last level, Box2D v3 1.90M and 0.80M: 4.9 and
  6.9 times as many, for 1.21 times the instructions (first level: 44.1M
  and 6.4M against 20.6M and 1.6M). carom's come from its contacts: the
  detection writing this step's list while it reads last step's
  (pair_pieces 1.62M and 2.07M), the set-up, by when the points the
  detection wrote have left the last level (contact_prepare_from 1.40M
  and 1.01M, contact_batch_prepare 1.53M and 1.06M), the warm start's
  first walk over the batches (0.68M), the events (0.58M) and the shock
  rows (0.37M and 0.37M); Box2D v3's from its collide task (0.63M and
  0.08M), its prepare (0.54M and 0.56M) and its bodies. A contact and its
  points take about 640 bytes in each of the two lists (last step's and
  this one's), and its batch lane 200 to 400 more: per contact carom
  streams about four times Box2D v3's bytes a step. Yet the bytes a
  step streams in order are not what it waits on: a point made 64 bytes
  larger (280 to 344, by a padding), and the same with the set-up
  writing those 64 bytes of every point each step, timed the same
  (`tools/compare-bench`, 12 pairs, settled rain: 1.004 and 0.999), so
  splitting a point into what the passes read and what the impacts keep
  would not pay for itself. What it waits on are reads the processor
  cannot foresee (a body, a piece, a contact reached through an index)
  and branches the data decide: callgrind's branch simulation over the
  same steps counts 57k mispredicted branches a step, 17k of them in the
  shock rows' passes (whether a row needs an impulse, 7.2k; the switch
  over a row's kind, 6.7k), 7.7k in the detection, 5k in the levels'
  walk.
  Since, the packing reads the contacts in list order, as the set-up
  left them, and writes each into the lane its colour gives it (the
  batches the same to the byte): it had read them in the colours' order,
  all over the list, and waited on those reads (`perf record`, settled
  rain, `warmup=450 steps=600`, two runs each: contact_batch_prepare
  9.05% and 6.79% of the samples before, 5.66% and 5.63% after;
  `tools/compare-bench`, 16 pairs: 0.942 and 1.011 settled, 0.965 and
  0.999 over the bench's steps, the pyramid 1.005). The same for the
  shock rows (their contacts read in list order, each row written at its
  place in the level order) took contact_shock_prepare from 5.2% and
  5.5% of the samples to 6.9% and 7.2%: not kept. The shock rows' own
  pass (a tenth of the settled rain's samples) is not waiting on memory
  or on its branches: the rows put in waves (each after every earlier
  row that writes a body it reads or writes, or reads one it writes: the
  same bits) with a wave's faces before its one-point rows, so that the
  switch over a row's kind no longer goes one way or the other at
  random, left its share where it was (10.7% and 10.9% of the samples,
  `tools/compare-bench` 0.997); and a second copy of the pass, run just
  before it on the same rows but pushing a dummy body, took 9.3% of the
  samples against the pass's 10.0%, which then ran on what the copy had
  brought into the caches. At about 40 cycles a row and 14.5k rows a
  step, it was the work itself. So the rows are now solved four at a
  time (lib/shock_batch.h): put in waves (a row one wave after the last
  that wrote either of its bodies; in level order that is all it needs),
  each wave's rows of one and of two points packed into batches of four
  lanes, and one kernel (lib/shock_kernel.h, portable and AVX2, the same
  bits) doing each lane's work by masks. The results are those of the
  rows one at a time to the bit (the four benchmarks' hashes, `build/stress
  --all` and `build/solver2d --all` byte for byte, the 57 scenes of
  scenes/ and fuzz/corpus/scene after 300 steps;
  `test_shock_waves_keep_the_level_order` compares the two at every step
  of a field of columns on both paths and both narrow phases). Settled
  rain (`perf record`, `warmup=450 steps=600`): the pass 9.1% of the
  samples before, 5.3% after, the set-up (which now also makes the waves
  and packs them) 5.7% and 8.0%; `tools/compare-bench`, 12 pairs: 0.901
  settled, 0.935 over the bench's steps; instructions over the rain's
  first 300 steps 3676M to 3619M (-1.5%). The set-up's share is mostly
  its reads of the contacts in level order, as before; it now reads only
  the contacts that make rows (found in the marks' walk down the levels:
  8.0% to 6.9% of the samples), and the kernel loads a body's motion
  only for a batch that needs its gaps (4.86% to 4.47%). Asking for each
  row's contact and points of the memory 8 and 4 rows ahead changed
  nothing (`tools/compare-bench` 1.011): not kept. The levels' walk makes
  its stores and moves its counts by selects, without branches (1.79% to
  1.37% of the samples), the same bits. The rows of one and two points go
  into their lanes straight from their contacts; only the rows of more
  points, and every row of a step that solves them one at a time, are
  made as rows (callgrind, `bench_carom scene=rain warmup=450 steps=60`,
  with the warm-up: the set-up 433.3M to 371.7M instructions, the whole
  6584.8M to 6537.3M; the same bits). The events match this update's
  touching pairs against the last one's in order, as the detection
  matches contacts, and hash the last one's only from the first pair that
  is not where it was: over the rain's bench window (`warmup=60
  steps=540`) 186.1M to 156.6M instructions, the same events in the same
  order for every scene of scenes/ and fuzz/corpus/scene over 600 steps.
  Without a bouncy contact (whose impacts would change the points after
  the set-up) the batches are laid out before the set-up, and each
  batched contact is packed into its lane as soon as it is set up, its
  points still in the caches (lib/contact_batch_pack.h; the cold start's
  contacts are packed again after it): the same bits, one read of the
  contacts fewer. cachegrind with a last level the size of this
  machine's L2 (`--D1=32768,8,64 --LL=1048576,8,64`, `bench_carom
  scene=rain warmup=450 steps=30`) counts 173.2M data misses at that
  level before, 165.0M after (-4.8%), for 0.2% more instructions;
  `tools/compare-bench` over the bench window, 30 pairs on the rain:
  0.981, 16 on the pyramid: 0.983.
- **The broad phase** is a sort and sweep below 4096 bodies and a uniform
  grid above (the sweep's strip tests grow as n sqrt(n) in crowded worlds:
  the gas at 100k bodies went from 65 to 42 ms per step with the grid, one
  run of `bench_carom scene=gas bodies=100000 steps=60` each). The grid
  finds each box's cells once a detection (it found them three times:
  sizing the grid, counting, placing), truncates instead of calling floor
  and compares instead of calling fmin and fmax, to the bit: callgrind
  over steps 61 to 80 took the rain at 10k bodies from 532.8M to 448.1M
  instructions and the gas from 570.8M to 488.7M; in time (`tools/compare-bench`,
  8 pairs) the gas 10k 0.887, the rain 10k 1.016: what the rain's step
  waits on at 10k bodies is not those instructions. The cell a pair is
  reported from (its overlap's low corner) is now the larger of the two
  boxes' kept first cells on each axis, as grid_cell never decreases,
  instead of two divisions a pair: the gas 10k 0.893 again (10 pairs),
  for 0.35% fewer instructions (the rain 10k 0.75% fewer, 1.013 in time).
  And the grid reports its pairs 64 at a
  time through the kept pairs' loop, the bodies of those ahead asked of
  the memory: the rain 10k 0.909 and 0.985, the gas 10k 1.136 and 0.945
  (two runs each on a noisy machine; the fastest runs 3% to 5% faster
  for the rain, 1% to 4% for the gas). What
  remains of the growth per body in the scaling table is memory: at 100k
  bodies the world no longer fits in the caches. Below 4096 bodies it
  keeps the pairs of overlapping fat boxes (each body's box grown by a
  tenth of its size) while few bodies leave their fat boxes, and then
  neither sorts nor sweeps (lib/broadphase.h): that took 6% off the
  pyramid's instructions (callgrind, 120 steps: 175.5M against 186.5M)
  and 0.9% off the rain's over its 600 steps (8.87G against 8.95G), which
  keeps its pairs from its fifth second on; the gas, whose bodies always
  move, sweeps every step, as before, for 0.5% more.
- **Sleeping is off in these runs** for every engine; with it on (the
  `sleep on` rows and docs/effects.md) a settled pyramid costs carom under a
  tenth of its awake time.
EOF
  if [ "$HAVE_B3" = yes ] && [ -n "$CHAIN_JOINTS" ]; then
    cm=$(med_ms carom chains)
    b3=$(med_ms box2d3 chains)
    share=""
    if [ "$PROFILE" = yes ]; then
      share=" (the joints'
  stages are $(joint_share "$B/profile-chains-inclusive.txt")% of its instructions in the chains profile above)"
    fi
    cat <<EOF
- **Joints** (the chains) cost carom $(per_joint_us "$cm" "$CHAIN_JOINTS") us per joint per step and Box2D v3
  $(per_joint_us "$b3" "$CHAIN_JOINTS") (carom / Box2D v3 $(ratio "$cm" "$b3")). Box2D v3 solves each joint on its own,
  soft, once per pass; carom solves every rigid row of a tree of joints
  together, exactly (lib/joint_tree.c), in each velocity pass (the solve
  and the relax pass of each sub-step), and projects the positions after
  each sub-step's move, which takes the block system of the tree to be set
  up and factored${share}.
  What that buys is measured in docs/accuracy.md (the pendulum, double
  pendulum, heavy chain and limit sections) and in the mean joint gap
  column of the chains table above.
EOF
  fi
} >"$OUT.tmp"
mv "$OUT.tmp" "$OUT"
echo "run-bench: wrote $OUT in ${ELAPSED} s" >&2
