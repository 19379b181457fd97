#!/bin/sh
# The GTK demo in a real X server: start Xvfb on a free display, run the
# demo on scenes/thesis.scene, drive it with xdotool (keys through XTEST,
# the mouse), dump the window with xwd and check the pictures: not blank,
# moving while running, still while paused, changed by `.`, `v`, `h` and a
# mouse drag; the drag's mouse joint pulls the body to the pointer; every
# key survives; `q` quits with status 0; --screenshot writes a PNG; a bad
# scene file fails with FILE:LINE.
#
# Usage: tests/test_demo_x11.sh [DEMO-BINARY]     (default build/carom-demo)
# Needs Xvfb, xdotool and xwd (tools/ensure-deps xtest). ImageMagick, if
# there, turns the dumps into PNGs. DEMO_X11_OUT=DIR keeps the pictures in
# DIR (else a temporary directory, removed at the end).
# Last line: "demo x11: N passed, N failed"; exit status 0 only if none
# failed.
set -u

DEMO=${1:-build/carom-demo}
SCENE=scenes/thesis.scene
LIMIT=${DEMO_X11_TIMEOUT:-180}   # seconds for the whole test

passed=0
failed=0
pass () { passed=$((passed + 1)); echo "ok   $*"; }
skip () { skipped=$((skipped + 1)); echo "skip $*"; }
fail () { failed=$((failed + 1)); echo "FAIL $*"; }

xvfb_pid=
demo_pid=
own_pid=
watchdog_pid=
keep=${DEMO_X11_OUT:+1}
if [ -n "${DEMO_X11_OUT:-}" ]; then
  OUT=$DEMO_X11_OUT
  mkdir -p "$OUT"
else
  OUT=$(mktemp -d "${TMPDIR:-/tmp}/carom-demo-x11.XXXXXX")
fi

cleanup () {
  trap - EXIT INT TERM HUP
  [ -n "$demo_pid" ] && kill "$demo_pid" 2>/dev/null
  [ -n "$own_pid" ] && kill "$own_pid" 2>/dev/null
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
  [ -n "$watchdog_pid" ] && kill "$watchdog_pid" 2>/dev/null
  [ -n "$demo_pid" ] && wait "$demo_pid" 2>/dev/null
  [ -n "$xvfb_pid" ] && wait "$xvfb_pid" 2>/dev/null
  [ -z "$keep" ] && rm -rf "$OUT"
}
finish () {
  echo "demo x11: $passed passed, $failed failed, ${skipped:-0} skipped"
  cleanup
  # an explicit status: a bare exit in a trap keeps the status from before it
  if [ "$failed" -eq 0 ]; then exit 0; fi
  exit 1
}
abort () {
  fail "$*"
  finish
}
trap cleanup EXIT
trap 'fail "interrupted or timed out after ${LIMIT}s"; finish' INT TERM HUP

for tool in Xvfb xdotool xwd; do
  command -v "$tool" >/dev/null 2>&1 || abort "$tool is not installed (tools/ensure-deps xtest)"
done
[ -x "$DEMO" ] || abort "$DEMO is not built (make demo)"
[ -f "$SCENE" ] || abort "$SCENE not found: run from the top of the source tree"

# The whole test is bounded: a hung X server or demo cannot block CI. The
# watchdog leaves our output alone (a pipe left open would hold up make)
# and ends within a second of us.
test_pid=$$
(
  i=0
  while [ $i -lt "$LIMIT" ]; do
    sleep 1
    kill -0 "$test_pid" 2>/dev/null || exit 0
    i=$((i + 1))
  done
  kill -TERM "$test_pid"
) </dev/null >/dev/null 2>&1 &
watchdog_pid=$!

# ------------------------------------------------------------------ X server

# Xvfb picks a free display itself (-displayfd) and writes its number once
# it accepts connections.
: >"$OUT/display"
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp -noreset 3>"$OUT/display" >"$OUT/xvfb.log" 2>&1 &
xvfb_pid=$!
i=0
while [ ! -s "$OUT/display" ] && [ $i -lt 100 ]; do
  kill -0 "$xvfb_pid" 2>/dev/null || break
  sleep 0.1
  i=$((i + 1))
done
[ -s "$OUT/display" ] || abort "Xvfb did not start (see $OUT/xvfb.log)"
DISPLAY=:$(tr -dc 0-9 <"$OUT/display")
# no accessibility bus on a bare server: do not let GTK look for one
NO_AT_BRIDGE=1
export DISPLAY NO_AT_BRIDGE
echo "Xvfb on $DISPLAY"
xdotool getdisplaygeometry >/dev/null 2>&1 || abort "cannot talk to Xvfb on $DISPLAY"

# ------------------------------------------------------------------ helpers

# shot NAME: dump the demo's window to $OUT/NAME.xwd (and .png if we can).
shot () {
  sleep 0.4 # a few frames, so what we asked for is on screen
  timeout 10 xwd -silent -id "$wid" -out "$OUT/$1.xwd" || fail "xwd could not dump the window for $1"
  if command -v convert >/dev/null 2>&1; then
    convert "xwd:$OUT/$1.xwd" "$OUT/$1.png" 2>/dev/null
  fi
}
same () { cmp -s "$OUT/$1.xwd" "$OUT/$2.xwd"; }

# Distinct 32-bit words in a dump: a blank window has a handful.
colours () { od -An -v -tx4 -w4 "$OUT/$1.xwd" | sort -u | wc -l; }

alive () { kill -0 "$demo_pid" 2>/dev/null; }

key () {
  timeout 5 xdotool key --delay 60 "$@" || fail "xdotool key $*"
}

# ------------------------------------------------------------------ the demo

"$DEMO" --verbose "$SCENE" >"$OUT/demo.log" 2>&1 &
demo_pid=$!
wid=$(timeout 15 xdotool search --sync --onlyvisible --pid "$demo_pid" 2>/dev/null | head -n 1)
[ -n "$wid" ] || wid=$(timeout 5 xdotool search --onlyvisible --name '^carom demo' 2>/dev/null | head -n 1)
[ -n "$wid" ] || abort "no demo window appeared (log: $(tr '\n' ' ' <"$OUT/demo.log"))"
pass "the demo window appears (id $wid)"

# No window manager: give the window the keyboard ourselves.
timeout 5 xdotool windowfocus "$wid" 2>/dev/null
sleep 0.5

shot running1
n=$(colours running1)
if [ "$n" -ge 200 ]; then pass "the window is not blank ($n distinct pixel words)"
else fail "the window looks blank: $n distinct pixel words"; fi

sleep 0.3
shot running2
if same running1 running2; then fail "the picture does not change while running"
else pass "the picture changes while running"; fi

key space
shot paused1
sleep 0.8
shot paused2
if same paused1 paused2; then pass "space pauses: the picture stays still"
else fail "the picture changes while paused"; fi

key period
shot stepped
if same paused2 stepped; then fail "'.' did not advance a frame while paused"
else pass "'.' advances one frame while paused"; fi

key v
shot vectors
if same stepped vectors; then fail "'v' did not show velocity arrows"
else pass "'v' shows velocity arrows"; fi
key v
shot vectors_off
if same stepped vectors_off; then pass "'v' again hides them (picture as before)"
else fail "'v' twice does not give the same picture back"; fi

key h
shot help
if same stepped help; then fail "'h' did not show the help"
else pass "'h' shows the help overlay"; fi
key h
shot help_off

# Restart (still paused), then drag the square (box at 4, 6.8 in the scene
# file): the demo prints its view, from which we find it on the screen.
# While the button is held the grab is a mouse joint: paused, the body
# stays put and the picture shows the pull (the body outlined, a line to
# the pointer); stepping with `.` lets the joint pull the grabbed point to
# the pointer, which the demo prints on release.
key r
shot restarted
if same help_off restarted; then fail "'r' did not restart the scene"
else pass "'r' restarts the scene"; fi
view=$(grep 'view' "$OUT/demo.log" | tail -n 1)
eval "$(timeout 5 xdotool getwindowgeometry --shell "$wid")"
pos=$(echo "$view" | awk -v wx=4 -v wy=6.8 -v ox="${X:-0}" -v oy="${Y:-0}" '{
  x0 = $3; y0 = $4; x1 = $5; y1 = $6; split ($8, s, "x"); w = s[1]; h = s[2];
  k = w / (x1 - x0); if (h / (y1 - y0) < k) k = h / (y1 - y0);
  printf "%d %d", ox + 0.5 * (w - (x1 - x0) * k) + (wx - x0) * k, oy + h - 0.5 * (h - (y1 - y0) * k) - (wy - y0) * k }')
if [ -n "$pos" ]; then
  set -- $pos
  timeout 5 xdotool mousemove "$1" "$2" mousedown 1 \
    mousemove "$(($1 + 20))" "$(($2 + 10))" mousemove "$(($1 + 60))" "$(($2 + 40))"
  shot holding
  if grep -q 'grab at' "$OUT/demo.log"; then pass "pressing on a body grabs it"
  else fail "no body grabbed at pixel $pos (view: $view)"; fi
  if same restarted holding; then fail "holding a body while paused shows nothing"
  else pass "holding a body while paused shows its pull"; fi
  key period period period period period period period period period period period period period period period \
    period period period period period period period period period period period period period period period
  timeout 5 xdotool mouseup 1
  shot dragged
  if same restarted dragged; then fail "dragging and stepping did not move the body"
  else pass "dragging and stepping moves the body"; fi
  # "release at X Y, the grabbed point at PX PY": within 0.15 m after half
  # a second of the joint's 5 Hz pull
  gap=$(grep 'release at' "$OUT/demo.log" | tail -n 1 | tr -d ',' | awk '{ dx = $4 - $10; dy = $5 - $11;
    printf "%.3f", sqrt (dx * dx + dy * dy) }')
  if [ -n "$gap" ] && awk -v g="$gap" 'BEGIN { exit !(g < 0.15) }'; then
    pass "the mouse joint pulls the grabbed point to the pointer (${gap} m off)"
  else
    fail "the grabbed point is ${gap:-?} m from the pointer after 30 steps ($(grep 'release at' "$OUT/demo.log" | tail -n 1))"
  fi
else
  fail "the demo did not print its view (--verbose)"
fi

# Every key, twice over, including scene switches: the demo must survive.
key 2 3 4 5 1 Up Up Left Right Down g g plus plus minus Page_Up Page_Down c c r v h h \
  space period period space KP_Add KP_Subtract equal question f d o s t f d o s t
key 6 7 8 9 0 n n p j j p p n 1
key Home F5 x BackSpace Tab Return
sleep 0.5
if alive; then pass "every key is survived"
else fail "the demo died during the key test"; fi

# Restitution: the bar shows up after + (the world is rebuilt keeping states).
key space
shot before_e
key minus
shot after_e
if same before_e after_e; then fail "'-' changed nothing on screen"
else pass "'-' lowers restitution and shows the bar"; fi
alive || fail "the demo died changing restitution"

# Resizing: the walls move (the demo prints the new view).
timeout 5 xdotool windowsize "$wid" 1000 700 2>/dev/null
sleep 1
if grep -q 'in 1000x676 px' "$OUT/demo.log" && alive; then pass "resizing the window refits the view"
else fail "no refit after resizing to 1000x700"; fi
shot resized

# Mouse play while running: throw whatever is in the middle, click on
# empty space, drag off the window.
key space
eval "$(timeout 5 xdotool getwindowgeometry --shell "$wid")"
cx=$((${X:-0} + ${WIDTH:-800} / 2)); cy=$((${Y:-0} + ${HEIGHT:-600} / 2))
timeout 10 xdotool mousemove "$cx" "$cy" mousedown 1 mousemove "$((cx + 30))" "$((cy - 20))" \
  mousemove "$((cx + 90))" "$((cy - 60))" mouseup 1 mousemove 5 5 click 1 \
  mousemove "$cx" "$((cy + 100))" mousedown 1 mousemove 2000 2000 mouseup 1 >/dev/null 2>&1
sleep 0.5
if alive; then pass "mouse grabs, throws and stray clicks are survived"
else fail "the demo died during the mouse test"; fi

key q
i=0
while alive && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
if alive; then fail "'q' did not quit"
else
  wait "$demo_pid"
  rc=$?
  demo_pid=
  if [ $rc -eq 0 ]; then pass "'q' quits with status 0"; else fail "'q' quit with status $rc"; fi
fi

# ------------------------------------------------------------ batch modes

if timeout 60 "$DEMO" --frames 30 --screenshot "$OUT/self.png" "$SCENE" >"$OUT/self.log" 2>&1 \
  && [ "$(head -c 4 "$OUT/self.png" | od -An -tx1 | tr -d ' \n')" = 89504e47 ]; then
  pass "--frames 30 --screenshot writes a PNG and exits 0"
else
  fail "--screenshot failed: $(tr '\n' ' ' <"$OUT/self.log")"
fi

timeout 60 "$DEMO" --paused --frames 5 --screenshot "$OUT/paused5.png" "$SCENE" >/dev/null 2>&1
timeout 60 "$DEMO" --paused --frames 25 --screenshot "$OUT/paused25.png" "$SCENE" >/dev/null 2>&1
if [ -s "$OUT/paused5.png" ] && cmp -s "$OUT/paused5.png" "$OUT/paused25.png"; then
  pass "--paused: the same picture after 5 and 25 frames"
else
  fail "--paused pictures differ (or are missing)"
fi

# The window shows the very pixels --screenshot saves: dump the window of
# a paused demo before it saves its own picture, compare the two.
if command -v compare >/dev/null 2>&1; then
  "$DEMO" --paused --frames 150 --screenshot "$OUT/own.png" "$SCENE" >/dev/null 2>&1 &
  own_pid=$!
  own_wid=$(timeout 15 xdotool search --sync --onlyvisible --pid "$own_pid" 2>/dev/null | head -n 1)
  sleep 0.8
  [ -n "$own_wid" ] && timeout 10 xwd -silent -id "$own_wid" -out "$OUT/own_window.xwd"
  wait "$own_pid"
  own_pid=
  ae=$(compare -metric AE "xwd:$OUT/own_window.xwd" "$OUT/own.png" null: 2>&1)
  if [ "$ae" = 0 ]; then pass "the window shows exactly what --screenshot saves"
  else fail "window dump and --screenshot differ (AE: $ae)"; fi
else
  skip "window vs --screenshot comparison: no ImageMagick"
fi

printf 'gravity 0 -10\nbox -1 1 at 0 0\n' >"$OUT/bad.scene"
timeout 20 "$DEMO" --frames 1 "$OUT/bad.scene" >"$OUT/bad.log" 2>&1
rc=$?
if [ $rc -eq 1 ] && grep -q "^$OUT/bad.scene:2: " "$OUT/bad.log"; then
  pass "a bad scene file: FILE:LINE: message, status 1"
else
  fail "bad scene file: status $rc, output: $(tr '\n' ' ' <"$OUT/bad.log")"
fi

[ -n "$keep" ] && echo "pictures in $OUT"
finish
