#!/usr/bin/env bash
# turb_cost.sh: what turbulence costs each model (issue 13: "turbulent wind costs no more than a few
# times steady wind"; BENCHMARKS.md "Two taut turbulent spans"). For each turbulent scene: `gallop
# simulate` of each model in the scene's wind and with wind.turbulence = none (the same mean speed),
# a 10-s and a T-s run (on_invalid = warn), each a process under /usr/bin/time; REPEAT repeats, the
# winds and models alternating. Prints per scene and model the median CPU (user + sys) per simulated
# second, (CPU(T) - CPU(10)) / (T - 10), turbulent over steady, and the T-s run's counters (steps,
# rejected steps, Newton iterations a step, factorizations, basis, valid) of the first repeat.
# Usage: tests/bench/turb_cost.sh [GALLOP [OUT]] SCENE...   Environment: T (300), REPEAT (3).
# A run OUT already holds (its rc file) is not run again.
set -eu
gallop=${1:-build/gallop}
out=${2:-out/turb_cost}
shift 2 || { echo "usage: turb_cost.sh GALLOP OUT SCENE..." >&2; exit 2; }
[ $# -gt 0 ] || { echo "usage: turb_cost.sh GALLOP OUT SCENE..." >&2; exit 2; }
T=${T:-300} REPEAT=${REPEAT:-3}
command -v jq >/dev/null || { echo "turb_cost.sh: needs jq" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "turb_cost.sh: needs /usr/bin/time" >&2; exit 2; }
mkdir -p "$out"
echo "load at start: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
for r in $(seq 1 "$REPEAT"); do
  for scene in "$@"; do
    n=$(basename "$scene" .ini)
    for wind in turbulent steady; do
      for m in reduced full; do
        for t in 10 "$T"; do
          d="$out/$n-$wind-$m-t$t-r$r"
          [ -s "$d/rc" ] && continue
          mkdir -p "$d"
          set_wind=""; [ $wind = steady ] && set_wind="--set wind.turbulence=none"
          /usr/bin/time -f "%U %S %e" -o "$d/time" "$gallop" simulate "$scene" --model $m -o "$d" \
            --set simulation.duration="$t" --set model.on_invalid=warn $set_wind >"$d/log" 2>&1 \
            && echo 0 >"$d/rc" || echo $? >"$d/rc"
        done
      done
    done
  done
done
echo "load at end: $(cut -d' ' -f1-3 /proc/loadavg)" >&2

cpu() { tail -n 1 "$1/time" | awk '{ printf "%.4f", $1 + $2 }'; }
echo "| scene | model | turbulent s per simulated s | steady | turbulent / steady | counters turbulent; steady (steps, rejected, Newton a step, factorizations, basis, valid) |"
echo "|---|---|---:|---:|---:|---|"
for scene in "$@"; do
  n=$(basename "$scene" .ini)
  for m in reduced full; do
    line="| $n | $m"; ratio=""
    for wind in turbulent steady; do
      per=$(for r in $(seq 1 "$REPEAT"); do
        a="$out/$n-$wind-$m-t10-r$r" b="$out/$n-$wind-$m-t$T-r$r"
        [ "$(cat "$a/rc")" = 0 ] && [ "$(cat "$b/rc")" = 0 ] || continue
        echo "$(cpu "$b") $(cpu "$a")" | awk -v T="$T" '{ printf "%.6f\n", ($1 - $2) / (T - 10) }'
      done | sort -g | awk '{ a[NR] = $1 } END { if (NR) print (NR % 2 ? a[(NR + 1) / 2] : 0.5 * (a[NR / 2] + a[NR / 2 + 1])) }')
      line="$line | ${per:-failed}"; ratio="$ratio ${per:-0}"
    done
    counters=""
    for wind in turbulent steady; do
      j="$out/$n-$wind-$m-t$T-r1/summary.json"
      c=$([ -s "$j" ] && jq -r '[.counters.steps, .counters.rejected_steps, (.counters.newton_iterations / .counters.steps * 100 | round / 100),
        .counters.factorizations, .counters.basis_modes, (if .valid == null then "-" else .valid end)] | map(tostring) | join(", ")' "$j" || echo "-")
      counters="$counters${counters:+; }$c"
    done
    echo "$line | $(echo "$ratio" | awk '{ if ($2 > 0) printf "%.2fx", $1 / $2; else printf "-" }') | $counters |"
  done
done
