#!/bin/sh
# Output format of the headless runner (docs/scenes.md): the key=value line,
# the CSV, FILE:LINE errors and exit statuses, the PNG/SVG files, the
# shipped jointed scenes.
# Usage: tests/test_runner.sh [CAROM]     (default build/carom)
# CAROM_WRAP runs every call under a wrapper, e.g.
#   CAROM_WRAP="valgrind -q --leak-check=full --error-exitcode=99" tests/test_runner.sh
carom=${1:-build/carom}
wrap=${CAROM_WRAP:-}
if [ ! -x "$carom" ]; then
  echo "test_runner: no runner at $carom (make runner)" >&2
  exit 1
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/carom-runner.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT HUP INT TERM
passed=0
failed=0

ok () { passed=$((passed + 1)); echo "ok - $1"; }
not_ok () { failed=$((failed + 1)); echo "not ok - $1"; }
check () { # check DESCRIPTION COMMAND...: pass when COMMAND succeeds
  what=$1; shift
  if "$@"; then ok "$what"; else not_ok "$what"; fi
}
# run EXPECTED-STATUS ARGS...: the runner's stdout, stderr in $tmp/out, $tmp/err
run () {
  want=$1; shift
  # shellcheck disable=SC2086
  $wrap "$carom" "$@" >"$tmp/out" 2>"$tmp/err"
  got=$?
  if [ "$got" -ne "$want" ]; then
    echo "# carom $*: exit $got, wanted $want" >&2
    sed 's/^/# stderr: /' "$tmp/err" >&2
    return 1
  fi
  return 0
}

# A small scene: two walls' worth of bounds, a ball, a box, a triangle.
cat >"$tmp/small.scene" <<'EOF'
# small test scene
gravity 0 -9.81
restitution 0.5
bounds 0 0 4 3
circle 0.3 at 1 1.5 velocity 1 0
box 0.5 0.4 at 2.5 1 angle 0.2
polygon 0 0 0.6 0 0 0.6 at 3 2.2 spin 1
EOF
printf 'gravity 0 -1\ncircle 1\ncircle 1 at 0 0 colour red\n' >"$tmp/bad.scene"

# ------------------------------------------------------------- key=value line
keys="bodies joints steps dt ms_per_step energy_start energy_end kinetic_start kinetic_end momentum_x momentum_y angular_momentum max_penetration contacts nan"
if run 0 run "$tmp/small.scene" --steps 30; then
  ok "run exits 0"
  check "run prints exactly one line" test "$(wc -l <"$tmp/out")" -eq 1
  line=$(cat "$tmp/out")
  missing=""
  for k in $keys; do
    case " $line " in
      *" $k="[-0-9]*) ;;
      *) missing="$missing $k" ;;
    esac
  done
  check "every key has a value (missing:${missing:- none})" test -z "$missing"
  check "bodies=7 steps=30" sh -c 'case "$1" in *"bodies=7 "*"steps=30 "*) exit 0;; esac; exit 1' - "$line"
  check "nan=0" sh -c 'case "$1" in *" nan=0 "*) exit 0;; esac; exit 1' - "$line"
  check "effects listed" sh -c 'case "$1" in *" effects="*) exit 0;; esac; exit 1' - "$line"
  check "dt defaults to 1/60" sh -c 'case "$1" in *" dt=0.01666666666666666"*) exit 0;; esac; exit 1' - "$line"
else
  not_ok "run exits 0"
fi

# ------------------------------------------------------------------------ CSV
header="id,kind,x,y,angle,vx,vy,spin,mass,inertia"
if run 0 run "$tmp/small.scene" --steps 5 --csv "$tmp/final.csv"; then
  check "CSV header" test "$(head -n 1 "$tmp/final.csv")" = "$header"
  check "CSV has one row per body" test "$(wc -l <"$tmp/final.csv")" -eq 8
  check "CSV kinds" test "$(cut -d, -f2 "$tmp/final.csv" | sort | uniq -c | tr -s ' ' | tr '\n' ';')" = " 1 circle; 1 kind; 6 polygon;"
  check "CSV rows have 10 fields" test "$(awk -F, 'NF != 10' "$tmp/final.csv" | wc -l)" -eq 0
else
  not_ok "run --csv exits 0"
fi
if run 0 run "$tmp/small.scene" --steps 10 --every 4 --csv "$tmp/every.csv"; then
  check "--every header has a step column" test "$(head -n 1 "$tmp/every.csv")" = "step,$header"
  # steps 0, 4, 8 and the last, 10
  check "--every rows at steps 0 4 8 10" test "$(tail -n +2 "$tmp/every.csv" | cut -d, -f1 | uniq | tr '\n' ' ')" = "0 4 8 10 "
else
  not_ok "run --every exits 0"
fi
if run 0 run "$tmp/small.scene" --steps 3 --csv -; then
  check "--csv - writes the CSV to stdout" test "$(head -n 1 "$tmp/out")" = "$header"
  check "--csv -: the key=value line comes last" sh -c 'tail -n 1 "$1" | grep -q "^bodies=7 "' - "$tmp/out"
else
  not_ok "run --csv - exits 0"
fi

# --------------------------------------------------------------------- errors
if run 1 run "$tmp/bad.scene"; then
  ok "a bad scene exits 1"
  check "the error reads FILE:LINE: message" grep -q "^$tmp/bad.scene:3: circle: unknown option 'colour'\$" "$tmp/err"
  check "nothing on stdout for a bad scene" test ! -s "$tmp/out"
else
  not_ok "a bad scene exits 1"
fi
check "a missing file exits 1" run 1 run "$tmp/none.scene"
check "a missing file: FILE: cannot open" grep -q "^$tmp/none.scene: cannot open: No such file" "$tmp/err"
check "check on a good scene" run 0 check "$tmp/small.scene"
check "check prints FILE: ok" test "$(cat "$tmp/out")" = "$tmp/small.scene: ok"
check "check on a bad scene exits 1" run 1 check "$tmp/bad.scene"
check "check reports FILE:LINE" grep -q "^$tmp/bad.scene:3: " "$tmp/err"

check "no arguments exits 2" run 2
check "unknown command exits 2" run 2 frobnicate "$tmp/small.scene"
check "unknown option exits 2" run 2 run "$tmp/small.scene" --colour
check "the message names the option" grep -q "unknown option '--colour'" "$tmp/err"
check "missing FILE exits 2" run 2 run --steps 3
check "negative --steps exits 2" run 2 run "$tmp/small.scene" --steps -1
check "non-numeric --steps exits 2" run 2 run "$tmp/small.scene" --steps 10x
check "--dt 0 exits 2" run 2 run "$tmp/small.scene" --dt 0
check "--dt nan exits 2" run 2 run "$tmp/small.scene" --dt nan
check "--substeps 0 exits 2" run 2 run "$tmp/small.scene" --substeps 0
check "--every without --csv exits 2" run 2 run "$tmp/small.scene" --every 2
check "--width without a value exits 2" run 2 run "$tmp/small.scene" --width
check "two files exit 2" run 2 run "$tmp/small.scene" "$tmp/small.scene"
check "--help exits 0" run 0 --help
check "--help shows usage" grep -q "^usage: carom run FILE" "$tmp/out"
check "--opt=value form and --substeps" run 0 run "$tmp/small.scene" --steps=2 --dt=0.01 --substeps=3

# ------------------------------------------------------------------- pictures
if run 0 run "$tmp/small.scene" --steps 10 --png "$tmp/out.png" --svg "$tmp/out.svg" --width 320; then
  check "--png writes a PNG" test "$(od -An -tx1 -N8 "$tmp/out.png" | tr -d ' \n')" = "89504e470d0a1a0a"
  # the PNG's width, big-endian at offset 16
  check "--width sets the PNG width" test "$(od -An -tu1 -j16 -N4 "$tmp/out.png" | tr -s ' ' | sed 's/^ //;s/ $//')" = "0 0 1 64"
  check "--svg writes an SVG" grep -q "<svg" "$tmp/out.svg"
else
  not_ok "run --png --svg exits 0"
fi
check "an unwritable --png exits 1" run 1 run "$tmp/small.scene" --steps 1 --png "$tmp/no/such/dir.png"

# ---------------------------------------------------------------- joints
# The shipped jointed scenes (run from the top of the source tree): they
# load, step and draw, with their joints counted.
for s in pendulum:4:3 bridge:28:21 ragdoll:20:9 car:7:2; do
  name=${s%%:*}; rest=${s#*:}; nb=${rest%%:*}; nj=${rest#*:}
  if run 0 run "scenes/$name.scene" --steps 120 --png "$tmp/$name.png" --width 200; then
    check "$name.scene: bodies=$nb joints=$nj nan=0" sh -c \
      'case "$1" in "bodies=$2 joints=$3 "*" nan=0 "*) exit 0;; esac; exit 1' - "$(cat "$tmp/out")" "$nb" "$nj"
    check "$name.scene: joints in effects" grep -q "effects=.*joints" "$tmp/out"
    check "$name.scene: --png draws it" test -s "$tmp/$name.png"
  else
    not_ok "run scenes/$name.scene exits 0"
  fi
done
printf 'circle 1 name a\njoint revolute world b at 0 0\n' >"$tmp/badjoint.scene"
if run 1 check "$tmp/badjoint.scene"; then
  check "a joint naming no body: FILE:LINE: message" \
    grep -q "^$tmp/badjoint.scene:2: joint revolute: no body is named 'b'\$" "$tmp/err"
else
  not_ok "a joint naming no body exits 1"
fi

echo "test_runner: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
