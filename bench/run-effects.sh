#!/bin/sh
# Measure what each effect stage costs per step and write docs/effects.md.
# usage: bench/run-effects.sh EFF_DIR [OUTPUT]    (make bench-effects calls it)
#
# EFF_DIR holds bench_effects; raw outputs and callgrind profiles are left in
# EFF_DIR/raw, never in git. Time: every variant of a scene stepped
# interleaved in one process, chunk by chunk; the whole run repeated, median
# of the repeats. Instructions: each variant alone under callgrind, counting
# exactly the same steps. Environment: EFFECTS_WARMUP (60), EFFECTS_STEPS
# (630), EFFECTS_CHUNK (10), EFFECTS_REPEATS (7), EFFECTS_JOBS (2: callgrind
# runs at once), EFFECTS_REUSE (1: measure nothing, write the report again
# from the raw outputs of the last run).
set -eu

B=${1:-build/effects}
OUT=${2:-docs/effects.md}
WARMUP=${EFFECTS_WARMUP:-60}
STEPS=${EFFECTS_STEPS:-630}
CHUNK=${EFFECTS_CHUNK:-10}
REPEATS=${EFFECTS_REPEATS:-7}
JOBS=${EFFECTS_JOBS:-2}
REUSE=${EFFECTS_REUSE:-0}
RAW=$B/raw
BIN=$B/bench_effects
ARGS="warmup=$WARMUP steps=$STEPS chunk=$CHUNK repeats=$REPEATS"
mkdir -p "$RAW" "$(dirname "$OUT")"
START=$(date +%s)

if [ ! -x "$BIN" ]; then
  echo "run-effects: $BIN is missing (make bench-effects-build)" >&2
  exit 1
fi

# key KEY LINE: the value of KEY in a key=value line
key () { printf '%s\n' "$2" | tr ' ' '\n' | sed -n "s/^$1=//p" | head -n 1; }

LOAD_START=$(cut -d' ' -f1-3 /proc/loadavg)
# the library measured: the tree as it is now, when make has just built it
REV=$(git rev-parse --short HEAD 2>/dev/null || echo "unknown")
DIRTY=$(git status --porcelain -- lib include 2>/dev/null | wc -l)

# ------------------------------------------------------------ time
if [ "$REUSE" = 1 ]; then
  echo "run-effects: reusing $RAW" >&2
else
  echo "run-effects: timing every variant, interleaved per scene ($REPEATS repeats of $WARMUP + $STEPS steps)" >&2
  # shellcheck disable=SC2086
  "$BIN" mode=time $ARGS >"$RAW/time.txt"
fi

# ------------------------------------------------------------ instructions
# Only measured_steps is counted: the timed steps, not building the scene or
# the warm-up. Ir per function (inclusive) of the stages that can be off.
"$BIN" mode=list >"$RAW/variants.txt"
HAVE_CALLGRIND=no
if [ "$REUSE" = 1 ]; then
  HAVE_CALLGRIND=yes
elif command -v valgrind >/dev/null 2>&1 && command -v callgrind_annotate >/dev/null 2>&1; then
  HAVE_CALLGRIND=yes
  echo "run-effects: callgrind on $(wc -l <"$RAW/variants.txt") variants, $JOBS at a time" >&2
  # shellcheck disable=SC2016 # the inner script expands its own arguments
  sed -n 's/^scene=\([^ ]*\) variant=\([^ ]*\) .*/\1 \2/p' "$RAW/variants.txt" |
    xargs -P "$JOBS" -L 1 sh -c '
      # $0 raw dir, $1 arguments, $2 binary, $3 scene, $4 variant
      out="$0/callgrind.$3.$4.out"
      # shellcheck disable=SC2086
      valgrind -q --tool=callgrind --callgrind-out-file="$out" --toggle-collect=measured_steps \
        "$2" mode=count scene="$3" variant="$4" $1 >"$0/count.$3.$4.txt" 2>&1 &&
        callgrind_annotate --auto=no --inclusive=yes --threshold=100 "$out" >"$0/profile.$3.$4.txt" 2>/dev/null
    ' "$RAW" "$ARGS" "$BIN" || HAVE_CALLGRIND=no
  # ir_* of a function: its inclusive Ir in the annotated profile
  : >"$RAW/count.txt"
  while read -r s v; do
    total=$(sed -n 's/^totals: //p' "$RAW/callgrind.$s.$v.out" 2>/dev/null || true)
    line="scene=$s variant=$v ir=${total:-0}"
    for f in gravity_kick damping_update sleep_wake_touched sleep_update solver_step contacts_update toi_first_touch \
      contact_impacts; do
      n=$(awk -v f=":$f " '
            index($0, f) && /^ *[0-9,]+ / { n = $1; gsub(",", "", n); print n; exit }' "$RAW/profile.$s.$v.txt" 2>/dev/null)
      line="$line ir_$f=${n:-0}"
    done
    echo "$line" >>"$RAW/count.txt"
  done <<EOF
$(sed -n 's/^scene=\([^ ]*\) variant=\([^ ]*\) .*/\1 \2/p' "$RAW/variants.txt")
EOF
fi

# ------------------------------------------------------------ merge
# One key=value line per variant: the timing line plus Ir per step and its
# ratio to the scene's baseline.
: >"$RAW/effects.txt"
while read -r l; do
  s=$(key scene "$l")
  v=$(key variant "$l")
  c=$(grep "^scene=$s variant=$v " "$RAW/count.txt" 2>/dev/null || true)
  c0=$(grep "^scene=$s variant=off " "$RAW/count.txt" 2>/dev/null || true)
  ir=$(key ir "$c")
  ir0=$(key ir "$c0")
  extra=$(awk -v a="${ir:-0}" -v b="${ir0:-0}" -v n="$STEPS" 'BEGIN {
    if (a > 0 && b > 0) printf "ir_per_step=%.0f ir_ratio=%.4f ir_diff_per_step=%.0f", a / n, a / b, (a - b) / n
    else printf "ir_per_step=- ir_ratio=- ir_diff_per_step=-" }')
  # the callgrind run should have ended where the timed ones did (glibc may
  # pick other libm code under valgrind, and a gas amplifies the last bit)
  same=yes
  for k in contacts asleep escaped; do
    [ "$(key $k "$(cat "$RAW/count.$s.$v.txt" 2>/dev/null)")" = "$(key $k "$l")" ] || same=no
  done
  echo "$(printf '%s\n' "$l" | sed 's/ ms_repeats=.*//') $extra same_end_under_callgrind=$same" >>"$RAW/effects.txt"
done <"$RAW/time.txt"
cat "$RAW/effects.txt"

# ------------------------------------------------------------ the report
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
mhz=$(sed -n 's/^cpu MHz[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
ccv=$(${CC:-cc} --version | head -n 1)
vgv=$(valgrind --version 2>/dev/null || echo "no valgrind")
LOAD_END=$(cut -d' ' -f1-3 /proc/loadavg)
ELAPSED=$(($(date +%s) - START))
WHEN=$(date -u '+%Y-%m-%d %H:%M UTC')
# the measuring run's circumstances, kept for EFFECTS_REUSE
if [ "$REUSE" = 1 ] && [ -f "$RAW/meta.txt" ]; then
  # shellcheck disable=SC1091
  . "$RAW/meta.txt"
else
  printf "ELAPSED='%s'\nWHEN='%s'\nLOAD_START='%s'\nLOAD_END='%s'\nREV='%s'\nDIRTY='%s'\n" "$ELAPSED" "$WHEN" \
    "$LOAD_START" "$LOAD_END" "$REV" "$DIRTY" >"$RAW/meta.txt"
fi

about () { sed -n "s/^scene=$1 variant=$2 kind=[^ ]* about=//p" "$RAW/variants.txt"; }
ir_of () { key "ir_$3" "$(grep "^scene=$1 variant=$2 " "$RAW/count.txt" 2>/dev/null || true)"; }
per_step () { awk -v a="${1:-0}" -v n="$STEPS" 'BEGIN { if (a > 0) printf "%.0f", a / n; else print "0" }'; }

scene_table () {
  echo "| variant | kind | what changes | active effects | ms/step (median) | ratio to off | ms/step (min) | Ir/step | Ir ratio | contact points at the end | bodies asleep | bodies escaped | max distance from the off world |"
  echo "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  grep "^scene=$1 " "$RAW/effects.txt" | while read -r l; do
    v=$(key variant "$l")
    echo "| $v | $(key kind "$l") | $(about "$1" "$v") | $(key effects "$l" | sed 's/,/, /g') | $(key ms_per_step "$l") | $(key ratio "$l") | $(key ms_min "$l") | $(key ir_per_step "$l") | $(key ir_ratio "$l") | $(key contacts "$l") | $(key asleep "$l") | $(key escaped "$l") | $(key dev_from_off "$l") |"
  done
}

# switch overhead: each idle variant against its scene's baseline
idle_table () {
  echo "| scene | variant | Ir/step, off | Ir/step, on but idle | difference per step | difference | trajectory |"
  echo "|---|---|---:|---:|---:|---:|---|"
  grep " kind=idle " "$RAW/effects.txt" | while read -r l; do
    s=$(key scene "$l")
    l0=$(grep "^scene=$s variant=off " "$RAW/effects.txt")
    d=$(key dev_from_off "$l")
    case $d in
    0) traj="identical to off" ;;
    *) traj="differs (bodies up to $d apart at the end)" ;;
    esac
    echo "| $s | $(key variant "$l") | $(key ir_per_step "$l0") | $(key ir_per_step "$l") | $(key ir_diff_per_step "$l") | $(awk -v r="$(key ir_ratio "$l")" 'BEGIN { if (r + 0 > 0) printf "%+.3f%%", 100 * (r - 1); else print "-" }') | $traj |"
  done
}

# stage_cell SCENE FUNCTION EFFECT...: Ir per step of the function in the off
# baseline, marked when one of the effects it runs is on in that scene
stage_cell () {
  s=$1
  f=$2
  shift 2
  on=$(key effects "$(grep "^scene=$s variant=off " "$RAW/effects.txt" || true)")
  mark=""
  for e in "$@"; do
    case ",$on," in *",$e,"*) mark=" (on: $e)" ;; esac
  done
  echo "$(per_step "$(ir_of "$s" off "$f")")$mark"
}

off_stage_table () {
  echo "| scene | gravity_kick (gravity, central) | damping_update | sleep_wake_touched | sleep_update | whole step |"
  echo "|---|---:|---:|---:|---:|---:|"
  for s in gas pyramid; do
    echo "| $s, off variant | $(stage_cell "$s" gravity_kick gravity central-gravity) | $(stage_cell "$s" damping_update damping) | $(stage_cell "$s" sleep_wake_touched sleeping) | $(stage_cell "$s" sleep_update sleeping) | $(per_step "$(key ir "$(grep "^scene=$s variant=off " "$RAW/count.txt" 2>/dev/null || true)")") |"
  done
}

# calls_of FILE FUNCTION: the calls of FUNCTION in callgrind output FILE
# (its names compressed: "fn=(id) name" once, "(id)" after)
calls_of () {
  awk -v f="$2" '
    /^c?fn=\(/ {
      s = $0; isc = (substr(s, 1, 1) == "c"); sub(/^c?fn=/, "", s)
      id = s; sub(/ .*/, "", id)
      if (index(s, " ")) { nm = s; sub(/^[^ ]* /, "", nm); name[id] = nm }
      if (isc) cur = name[id]
      next
    }
    /^calls=/ { if (cur == f) { n = $0; sub(/^calls=/, "", n); sub(/ .*/, "", n); total += n } }
    END { print total + 0 }' "$1" 2>/dev/null || echo 0
}

# what continuous collision does and costs, off against on, per step
continuous_table () {
  echo "| scene | variant | touches found | time-of-impact searches | Ir in the searches | Ir in the detection | Ir in the step's impacts | Ir/step |"
  echo "|---|---|---:|---:|---:|---:|---:|---:|"
  for s in gas pyramid; do
    for v in off continuous; do
      out="$RAW/callgrind.$s.$v.out"
      echo "| $s | $v | $(awk -v a="$(calls_of "$out" bracketed)" -v n="$STEPS" 'BEGIN { printf "%.2f", a / n }') | $(awk -v a="$(calls_of "$out" toi_first_touch)" -v n="$STEPS" 'BEGIN { printf "%.2f", a / n }') | $(per_step "$(ir_of "$s" "$v" toi_first_touch)") | $(per_step "$(ir_of "$s" "$v" contacts_update)") | $(per_step "$(ir_of "$s" "$v" contact_impacts)") | $(per_step "$(key ir "$(grep "^scene=$s variant=$v " "$RAW/count.txt" 2>/dev/null || true)")") |"
    done
  done
}

# the gas's touches and Ir, continuous over off, as percentages
continuous_gas_sentence () {
  t0=$(calls_of "$RAW/callgrind.gas.off.out" bracketed)
  t1=$(calls_of "$RAW/callgrind.gas.continuous.out" bracketed)
  i0=$(key ir "$(grep "^scene=gas variant=off " "$RAW/count.txt" 2>/dev/null || true)")
  i1=$(key ir "$(grep "^scene=gas variant=continuous " "$RAW/count.txt" 2>/dev/null || true)")
  awk -v t0="${t0:-0}" -v t1="${t1:-0}" -v i0="${i0:-0}" -v i1="${i1:-0}" 'BEGIN {
    if (t0 > 0 && i0 > 0 && t1 > t0)
      printf "In the gas, continuous collision finds %+.0f%% touches (%d against %d over the run) and costs %+.1f%% instructions: %.0f Ir for each touch it adds, where the off world spends %.0f Ir of its whole step per touch it finds.", 100 * (t1 / t0 - 1), t1, t0, 100 * (i1 / i0 - 1), (i1 - i0) / (t1 - t0), i0 / t0
  }'
}

stage_on_table () {
  echo "| scene | variant | stage function | Ir/step in it | share of the step |"
  echo "|---|---|---|---:|---:|"
  for sv in gas:gravity-tiny:gravity_kick gas:central-tiny:gravity_kick gas:damping-tiny:damping_update \
            gas:sleeping:sleep_update gas:sleeping:sleep_wake_touched pyramid:sleeping:sleep_update \
            pyramid:sleeping:sleep_wake_touched pyramid:damping:damping_update pyramid:central:gravity_kick; do
    s=${sv%%:*}
    rest=${sv#*:}
    v=${rest%%:*}
    f=${rest#*:}
    a=$(ir_of "$s" "$v" "$f")
    t=$(key ir "$(grep "^scene=$s variant=$v " "$RAW/count.txt" 2>/dev/null || true)")
    echo "| $s | $v | $f | $(per_step "$a") | $(awk -v a="${a:-0}" -v t="${t:-0}" 'BEGIN { if (t > 0) printf "%.2f%%", 100 * a / t; else print "-" }') |"
  done
}

{
  cat <<EOF
# What each effect costs

Generated by \`make BUILD=$(dirname "$B") bench-effects\` (bench/run-effects.sh, bench/bench_effects.c)
on $WHEN, in ${ELAPSED} s, from the library at commit $REV$([ "$DIRTY" -gt 0 ] && echo " with $DIRTY uncommitted change(s) in lib/ or include/"). Do not edit by
hand: run it again.

Machine: $(nproc) cores, $cpu (${mhz} MHz), load average $LOAD_START at the start and
$LOAD_END at the end (other work shares this machine: times are noisy, the
instruction counts are not). Compiler: $ccv, \`-O2 -g\`, carom linked
statically. $vgv.

## The effects

The update of a world is detect, solve and drift, plus the stages below. Each
is off until a scene or the API asks for it, but continuous collision, which
is on until it is switched off. A stage that is off returns at
once (it tests its switch once per sub-step). \`carom_world_get_effects\` reports
the active ones as bits of \`carom_effect\`; a scene file may name them with
\`effects NAME...\` (docs/scenes.md).

| effect | what it does | API | scene file | off when |
|---|---|---|---|---|
| gravity | uniform acceleration of every dynamic body | \`carom_world_set_gravity (w, gx, gy)\` or \`carom_world_def.gravity_x/_y\` | \`gravity GX GY\` | gravity is (0, 0) |
| central-gravity | attraction to a fixed point mass: acceleration gm / (r² + softening²) toward it | \`carom_world_set_central_gravity (w, x, y, gm, softening)\` | \`central X Y GM [SOFTENING]\` | gm = 0 |
| restitution | contacts bounce: an impact leaves at e times its approach speed (a contact takes the larger e of its two bodies) | \`carom_world_set_restitution (w, e)\`, \`carom_world_def.restitution\`, \`carom_body_def.restitution\` | \`restitution E\` (setting, or body option) | every e is 0 |
| friction | Coulomb friction at contacts, mu = sqrt(mu_a mu_b) | \`carom_world_set_friction (w, mu)\`, \`carom_world_def.friction\`, \`carom_body_def.friction\` | \`friction MU\` (setting, or body option) | every mu is 0 |
| fixed-rotation | a body that never turns (infinite inertia, spin 0) | \`carom_body_set_fixed_rotation (w, id, 1)\` | body option \`fixed\` | no body is fixed |
| damping | velocities decay as exp(-linear t), spins as exp(-angular t) | \`carom_world_set_damping (w, linear, angular)\` | \`damping LINEAR [ANGULAR]\` | both rates are 0 |
| sleeping | bodies at rest for half a second stop being simulated until touched | \`carom_world_set_sleeping (w, 1)\` | \`effects sleeping\` | by default |
| continuous | contacts of every body looked for as far ahead as the bodies can close on each other in the step, an inelastic pair as far as either goes if the other is stopped (otherwise only for bodies that move more than half their size in a step, which are always swept; others look 2% of their size ahead, but for pieces in contact the step before that do not bounce): no tunnelling, impacts solved at their time within the step | \`carom_world_set_continuous (w, 1)\`, \`carom_body_set_bullet (w, id, 1)\` | on by default; \`continuous 0\` switches it off, body option \`bullet\` keeps it for one body | \`carom_world_set_continuous (w, 0)\` (bodies fast for their size, and bullets, keep it) |

Gravity (0, 0) and damping (0, 0) are *off* by definition (the stage returns at
its first test), as is central gravity with gm = 0: there is no "on but zero"
to measure for them. The nearest thing is a value so small that it changes
nothing, which is what the *idle* rows below use. Fixed rotation has no stage
at all: a fixed body has zero inverse inertia, and the solver does the same
work for it as for any body.

## How it is measured

* Scenes from bench/scenes.c, built as bench/bench_carom.c builds them (every
  body takes the world's restitution and friction):
  * **gas**: 500 polygons (boxes, triangles, pentagons, hexagons, size 0.5 to 1)
    with random velocities |v| <= 5 in a closed box about 46 x 44, no gravity,
    restitution 1, friction 0;
  * **pyramid**: 20 rows of 1 x 1 boxes (210) on a static ground, gravity -10,
    friction 0.6, restitution 0.
* Variants: **off** is the scene as defined with every effect off, continuous
  collision (on by default) switched off too; **on** switches one effect on (or
  changes it) so that it does something; **idle** switches it on with a value
  that does (next to) nothing; **stage-off** switches off an effect the scene
  itself uses (its cost is then the baseline over this row).
* dt = 1/60, 4 sub-steps, 1 iteration (the defaults); $WARMUP warm-up steps,
  then $STEPS timed steps. All variants of a scene live in one process and are
  stepped interleaved, $CHUNK steps of one, then $CHUNK of the next, the order
  rotating, so machine noise hits them alike. The whole run (fresh worlds,
  warm-up, timed steps) is repeated $REPEATS times; a repeat's figure is its mean
  over all timed steps, as an instruction count is (a scene's cost changes as
  it evolves: a median over short windows would not match). **ms/step** is the
  median over the repeats (the minimum beside it), **ratio** is that median
  over the off variant's.
* **Ir/step**: instructions counted by \`valgrind --tool=callgrind
  --toggle-collect=measured_steps\` (a function of the bench around the timed
  steps only), each variant alone, over exactly the same $WARMUP + $STEPS steps
  as the timing (the simulation is deterministic), divided by $STEPS. Instructions
  do not show cache misses or slow divisions, but they repeat to the
  instruction on a busy machine.
* **bodies escaped**: dynamic bodies whose centre ended outside the
  container (the gas box; the pyramid's ground, 10 units either side, up to
  its height plus 1), or not finite.
* **max distance from the off world**: after all steps, the largest distance
  between a body and the same body in the off variant. 0 means the effect did
  not change a single bit of the trajectory, so any difference in Ir is the
  cost of the switch itself. A gas is chaotic: any change that does alter a bit
  grows until the two runs share nothing, and then their contact counts and
  costs differ by chance.

## Gas (500 polygons, e = 1, no gravity)

$(scene_table gas)

## Pyramid (210 boxes, gravity, friction 0.6)

$(scene_table pyramid)

$(if grep -q "same_end_under_callgrind=no" "$RAW/effects.txt"; then
  echo "**Warning**: under callgrind these variants ended in another state than in the"
  echo "timed runs (contact points, bodies asleep or escaped differ), so their Ir"
  echo "counts another trajectory: $(grep "same_end_under_callgrind=no" "$RAW/effects.txt" | while read -r l; do printf '%s/%s ' "$(key scene "$l")" "$(key variant "$l")"; done)"
else
  echo "Every callgrind run ended in the state the timed runs ended in (same contact"
  echo "points, bodies asleep and escaped), as it should."
fi)

## Continuous collision: what it does, and its cost

Continuous collision looks at a bouncy pair as far ahead as its bodies can
close on each other within the step, finds each touch at its time (toi.c)
and strikes it there (impact.c); off, a pair looks 2% of its bodies' size
ahead (bodies fast for their size excepted), and a touch that comes later
within the step is left to the sub-steps, which stop the bodies where they
overlap and push the overlap out. Per step of each scene, from the callgrind
runs above: the touches the time of impact found (calls of toi.c's
\`bracketed\`, each an impact solved at its time), its searches (calls of
\`toi_first_touch\`), and the Ir inclusive of \`toi_first_touch\` (the
searches, wherever made), \`contacts_update\` (the detection) and
\`contact_impacts\` (the step's impacts, their searches included):

$(continuous_table)

$(continuous_gas_sentence) Each touch it adds is an impact the off world
does not solve but lets the bodies overlap for (the elastic gas's deepest
overlap with it off: docs/accuracy.md). The pyramid rests: no touch to
find, the switch's test alone.

## The switch itself: on but idle against off

Each idle variant against the off baseline of its scene. Where the trajectory
is identical to off, the difference is exactly what the switch costs.

$(idle_table)

Ir per step spent in the optional stages while they are **off** (the call and
the test of the switch), in the off baseline of each scene (a stage the scene
itself uses is marked on):

$(off_stage_table)

Ir per step inside a stage function when it is on (inclusive):

$(stage_on_table)

Raw outputs: \`$RAW/effects.txt\` (one key=value line per variant),
\`$RAW/time.txt\` (every repeat), \`$RAW/callgrind.*.out\` and
\`$RAW/profile.*.txt\` (not in git). Re-run one variant by hand:

    $B/bench_effects mode=list
    $B/bench_effects mode=time scene=gas $ARGS
    valgrind --tool=callgrind --toggle-collect=measured_steps \\
      $B/bench_effects mode=count scene=gas variant=sleeping $ARGS
EOF
} >"$OUT.tmp"
mv "$OUT.tmp" "$OUT"
[ "$HAVE_CALLGRIND" = yes ] || echo "run-effects: callgrind missing or failed: no instruction counts" >&2
echo "run-effects: wrote $OUT in ${ELAPSED} s" >&2
