#!/usr/bin/env bash
# spanset.sh: issue 13's figures over the span set of tests/rom/ (`make report-spanset`, 20-60 min;
# not in make check). For every span:
# - accuracy: `gallop compare` at the span's own mesh and at 100 and 125 elements, the span's own
#   duration; per family the error against the issue's limit (frequency 1%; vertical p-p 5%;
#   horizontal 5% or 2% of the vertical p-p; twist 5% or 3 deg; largest support tension over the
#   steady window 5%), the reduced run's residual_max, valid and basis. Steady wind: compare's
#   headline figures (each family at the probe where the full model moves most, over the full run's
#   steady window). Turbulent wind (wind.seed = 1..SEEDS) and a span whose header says "statistics
#   over perturbed runs" (wind ramp + 0..SEEDS-1 s): the RMS about the mean of compare.csv's headline
#   columns over the window [max(steady_from_s, duration/2), end], frequency and tension as compare
#   gives them, each the mean over the runs. Where the reduced model refuses (exit 1), the same
#   compare again with model.on_invalid = warn (OUT/acc/RUN-warn) says how far off it was.
# - speed: `gallop simulate --model full|reduced` (alternating) at 100, 125 and 400 elements, a
#   SPEED_T-s run (default 300) and a 10-s run, each a process of its own under /usr/bin/time: CPU
#   time (user + sys) of the whole process; per simulated second (CPU(SPEED_T) - CPU(10)) /
#   (SPEED_T - 10), which takes the set-up out (at 400 elements a SPEED_T400-s run, default SPEED_T:
#   only its per-simulated-second figure is asked for). The wind is the scene's (its seed / ramp).
#   REPEAT (default 3) repeats of the 100-element speed runs of NOISE_SPANS say how noisy it is.
# Prints the tables and the medians over the set; everything is kept in OUT. A run OUT already holds
# (its rc file) is not run again: remove OUT to measure anew.
# Usage: tests/bench/spanset.sh [GALLOP [OUT]]   (defaults build/gallop, out/spanset)
# Environment: JOBS (parallel processes, default 1), SEEDS (3), SPEED_T (300), REPEAT (3),
# SPEED_T400, NOISE_SPANS ("drake_200_level_dshape falcon_400_incline80"), SPANS (default every
# tests/rom/*.ini), STAGE (all | run | table: run only, or only tabulate what OUT holds).
set -eu
gallop=${1:-build/gallop}
out=${2:-out/spanset}
JOBS=${JOBS:-1} SEEDS=${SEEDS:-3} SPEED_T=${SPEED_T:-300} SPEED_T400=${SPEED_T400:-$SPEED_T} REPEAT=${REPEAT:-3}
STAGE=${STAGE:-all}
NOISE_SPANS=${NOISE_SPANS:-"drake_200_level_dshape falcon_400_incline80"}
SPANS=${SPANS:-$(ls tests/rom/*.ini)}
command -v jq >/dev/null || { echo "spanset.sh: needs jq" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "spanset.sh: needs /usr/bin/time (Debian: time)" >&2; exit 2; }
mkdir -p "$out"

ini_get() { awk -F'=' -v k="$2" '$1 ~ "^"k"[ \t]*$" { sub(/;.*/, "", $2); gsub(/[ \t]/, "", $2); print $2; exit }' "$1"; }
own_elements() { ini_get "$1" elements; }
is_turbulent() { t=$(ini_get "$1" turbulence); [ -n "$t" ] && [ "$t" != none ]; }
is_statistics() { awk '/^;/ { if (index($0, "statistics over perturbed runs")) y = 1; next } { exit } END { exit !y }' "$1"; }
nruns() { if is_turbulent "$1" || is_statistics "$1"; then echo "$SEEDS"; else echo 1; fi; }
# the --set of run k (0-based) of a span
run_set() {
  if is_turbulent "$1"; then echo "wind.seed=$(($2 + 1))"
  elif is_statistics "$1"; then echo "simulation.wind_ramp=$(awk -v a="$(ini_get "$1" wind_ramp)" -v k="$2" 'BEGIN { print a + k }')"
  else echo ""; fi
}
meshes() { echo "$(own_elements "$1") 100 125" | tr ' ' '\n' | awk '!seen[$1]++' | tr '\n' ' '; }

# the tasks in the order of what matters most when the time is short: the accuracy at each span's own
# mesh, the speed at 100 and 125 elements, the accuracy at 100 and 125, the speed at 400, the
# repeats, the refused runs again with on_invalid = warn
tasks() {
  local s n e k r t m reps
  for pass in own spd acc 400 rep warn; do
    for s in $SPANS; do
      n=$(basename "$s" .ini)
      case $pass in
        own|acc|warn)
          for e in $(meshes "$s"); do
            [ $pass = own ] && [ "$e" != "$(own_elements "$s")" ] && continue
            [ $pass = acc ] && [ "$e" = "$(own_elements "$s")" ] && continue
            for k in $(seq 0 $(($(nruns "$s") - 1))); do echo "$([ $pass = warn ] && echo warn || echo acc) $s $n $e $k"; done
          done ;;
        spd|400|rep)
          for e in 100 125 400; do
            { [ $pass = 400 ] && [ $e != 400 ]; } || { [ $pass != 400 ] && [ $e = 400 ]; } && continue
            [ $pass = rep ] && [ $e != 100 ] && continue
            reps=1
            case " $NOISE_SPANS " in *" $n "*) [ $pass = rep ] && reps=$REPEAT ;; *) [ $pass = rep ] && continue ;; esac
            for r in $(seq $([ $pass = rep ] && echo 2 || echo 1) "$reps"); do
              for t in 10 "$([ $e = 400 ] && echo "$SPEED_T400" || echo "$SPEED_T")"; do
                for m in full reduced; do echo "spd $s $n $e $m $t $r"; done
              done
            done
          done ;;
      esac
    done
  done
}

# one task (a line of tasks()): its directory gets rc, time (user sys wall), the outputs
one_task() {
  set -- $1
  if [ "$1" = acc ]; then
    d="$out/acc/$3-e$4-r$5"
    [ -s "$d/rc" ] && return 0
    mkdir -p "$d"
    set_run=$(run_set "$2" "$5")
    nice /usr/bin/time -f "%U %S %e" -o "$d/time" "$gallop" compare "$2" -o "$d" --set model.elements="$4" \
      ${set_run:+--set "$set_run"} >"$d/log" 2>&1 && echo 0 >"$d/rc" || echo $? >"$d/rc"
  elif [ "$1" = warn ]; then
    # the reduced model refused (exit 1): again with model.on_invalid = warn, to see how far off it was
    d="$out/acc/$3-e$4-r$5"
    { [ "$(cat "$d/rc" 2>/dev/null)" = 1 ] && grep -q "the reduced model failed" "$d/log" && [ ! -s "$d-warn/rc" ]; } || return 0
    set_run=$(run_set "$2" "$5")
    d="$d-warn"
    mkdir -p "$d"
    nice /usr/bin/time -f "%U %S %e" -o "$d/time" "$gallop" compare "$2" -o "$d" --set model.elements="$4" \
      ${set_run:+--set "$set_run"} --set model.on_invalid=warn >"$d/log" 2>&1 && echo 0 >"$d/rc" || echo $? >"$d/rc"
  else
    d="$out/spd/$3-e$4-$5-t$6-r$7"
    [ -s "$d/rc" ] && return 0
    mkdir -p "$d"
    nice /usr/bin/time -f "%U %S %e" -o "$d/time" "$gallop" simulate "$2" --model "$5" -o "$d" \
      --set model.elements="$4" --set simulation.duration="$6" >"$d/log" 2>&1 && echo 0 >"$d/rc" || echo $? >"$d/rc"
  fi
  echo "$(date +%T) $* -> rc $(cat "$d/rc")" >&2
}
export -f one_task ini_get is_turbulent is_statistics run_set
export out gallop

if [ "$STAGE" != table ]; then
  {
    echo "gallop: $("$gallop" --version 2>/dev/null | head -1)"
    echo "commit: $(git rev-parse --short HEAD 2>/dev/null)$(git diff --quiet HEAD -- src include 2>/dev/null || echo ' (src modified)')"
    echo "machine: $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
    echo "started: $(date -u +%FT%TZ), load: $(cut -d' ' -f1-3 /proc/loadavg)"
  } >>"$out/meta"   # appended: a resumed run keeps the first start
  tasks | xargs -P "$JOBS" -I{} bash -c 'one_task "$@"' _ {}
  echo "finished: $(date -u +%FT%TZ), load: $(cut -d' ' -f1-3 /proc/loadavg)" >>"$out/meta"
fi
[ "$STAGE" = run ] && exit 0
exec bash "$(dirname "$0")/spanset_table.sh" "$out"
