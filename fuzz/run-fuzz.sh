#!/bin/sh
# Run each libFuzzer target on its committed seed corpus and report how many
# inputs it executed; fail on any finding.
# Usage: fuzz/run-fuzz.sh FUZZ_DIR LIMIT "EXTRA LIBFUZZER FLAGS" TARGET...
#
# LIMIT is a number of seconds per target (make fuzz: the search goes on from
# where the last run left it, new inputs kept in FUZZ_DIR/corpus/TARGET), or
# `smoke` (make check and CI): a fixed number of runs per target from the
# committed seeds alone, with -seed=1, whatever the machine's speed. The
# seeds are named in one list sorted by name (-seed_inputs), not read from
# their directory, whose order is the file system's: libFuzzer keeps seeds
# of equal size in the order it gets them. Every committed seed runs on
# every machine; the mutations after them still vary a little from run to
# run (libFuzzer's own choices are not all reproducible: two runs here of
# the same binary kept 1204 and 1244 new inputs), so a finding there is a
# sample of what `make fuzz` searches for longer.
# fuzz/corpus/TARGET, the committed seeds, is only read. A finding is saved
# as FUZZ_DIR/artifacts/TARGET-crash-... (or leak-, timeout-, oom-): replay it
# with FUZZ_DIR/fuzz_TARGET FILE.
dir=$1 limit=$2 extra=$3
shift 3
total=0 bad=""
for t in "$@"; do
  case $t in
  scene) max_len=8192; dict="-dict=fuzz/scene.dict" ;;
  polygon) max_len=20000; dict="" ;;
  *) max_len=4096; dict="" ;;
  esac
  if [ "$limit" = smoke ]; then
    # about 10 s each on one core of this machine
    case $t in
    scene) bound="-runs=30000" ;;
    polygon) bound="-runs=1500" ;;
    *) bound="-runs=20000" ;;
    esac
    work="$dir/smoke-corpus/$t"
    rm -rf "$work"
    mkdir -p "$work"
    LC_ALL=C ls "fuzz/corpus/$t" | sed "s|^|fuzz/corpus/$t/|" | paste -s -d, - >"$dir/smoke-seeds-$t"
    bound="$bound -seed=1 -seed_inputs=@$dir/smoke-seeds-$t"
    seeds=""
  else
    bound="-max_total_time=$limit"
    work="$dir/corpus/$t"
    seeds="fuzz/corpus/$t"
  fi
  mkdir -p "$work" "$dir/artifacts"
  log="$dir/fuzz_$t.log"
  # -timeout: one input running longer is a finding (a hang);
  # -rss_limit_mb: so is using more memory than this
  # shellcheck disable=SC2086
  "$dir/fuzz_$t" $bound -max_len=$max_len -timeout=25 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$dir/artifacts/$t-" $dict $extra \
    "$work" $seeds >"$log" 2>&1
  rc=$?
  runs=$(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\1/p' "$log" | tail -n 1)
  secs=$(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\2/p' "$log" | tail -n 1)
  cov=$(sed -n 's/^#[0-9]*.*DONE *cov: \([0-9]*\) ft: \([0-9]*\).*/cov \1, ft \2/p' "$log" | tail -n 1)
  if [ "$rc" -ne 0 ] || [ -z "$runs" ]; then
    echo "fuzz: $t: FINDING (exit status $rc); the end of $log:"
    grep -E 'FINDING|ERROR|runtime error|SUMMARY|Test unit written|artifact_prefix|==[0-9]+==|#[0-9]+ in ' "$log" | head -n 40
    bad="$bad $t"
    continue
  fi
  total=$((total + runs))
  echo "fuzz: $t: $runs runs in $secs s, no finding ($cov, corpus $(ls "$work" | wc -l) files)"
done
if [ -n "$bad" ]; then
  echo "fuzz: FAILED:$bad (inputs in $dir/artifacts/)"
  echo "fuzz: $(( $# - $(echo $bad | wc -w) )) passed, $(echo $bad | wc -w) failed"
  exit 1
fi
echo "fuzz: $# targets, $total runs, no finding"
echo "fuzz: $# passed, 0 failed"
