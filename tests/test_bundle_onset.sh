#!/usr/bin/env bash
# test_bundle_onset.sh: `gallop stability` on an explicit twin bundle (quad_bundle_gallop.ini with
# two sub-conductors, 24 elements, 2 spacers): the coupled onset it finds against the full model's
# own runs (`simulate --model full`, 400 s) a speed below and a speed above it: the growth rate of
# the mid-span vertical envelope (log of the peaks, least squares, after 100 s: the start's
# transient, which a window from 40 s of a 160-s run still held, +27% at 5 m/s) has the sign of the
# linear analysis's least-damped mode at that speed and is within 10% of its Re(lambda).
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch bundle_onset
sc=data/scenes/quad_bundle_gallop.ini
set_=(--set bundle.model=explicit --set bundle.subconductors=2 --set model.elements=24 --set bundle.spacers=2)
if "$GALLOP" stability $sc -o "$tmp/st" "${set_[@]}" --set stability.speed_min=1 --set stability.speed_max=6 \
    --set stability.speed_step=0.5 > "$tmp/st.txt" 2>&1; then ok "stability runs on the explicit twin"
else bad "stability: $(cat "$tmp/st.txt")"; fi
onset=$(sed -n 's/^  onset \([0-9.]*\) m\/s.*/\1/p' "$tmp/st.txt")
awk -v u="$onset" 'BEGIN { exit !(u > 1.5 && u < 5) }' && ok "onset $onset m/s inside 1.5 .. 5" || bad "onset '$onset'"
# Re(lambda) of the least-damped followed mode at speed U from vg.csv
linear() {
    awk -F, -v u="$1" 'NR == 2 { for (i = 1; i <= NF; i++) if ($i ~ /^f[0-9]+_hz$/) fc[++n] = i }
        NR > 2 && $1 + 0 == u + 0 { best = -1e9; for (k = 1; k <= n; k++) { f = $fc[k]; z = $(fc[k] + 1);
            g = -z * 6.283185307 * f / sqrt(1 - z * z); if (g > best) best = g } printf "%.6g", best }' "$tmp/st/vg.csv"
}
for U in 1.5 5; do
    "$GALLOP" simulate $sc --model full -o "$tmp/s$U" "${set_[@]}" --set wind.speed=$U --set simulation.duration=400 \
        > "$tmp/s$U.txt" 2>&1 || bad "simulate at $U m/s: $(cat "$tmp/s$U.txt")"
    g=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "p0.5_vertical_m") c = i; next }
        $1 >= 100 { t[++n] = $1; v[n] = $c; s += $c }
        END { m = s / n; for (i = 2; i < n; i++) { a = v[i] - m;
                if (a > 0 && a > v[i - 1] - m && a >= v[i + 1] - m) { k++; x = t[i]; y = log(a); sx += x; sy += y; sxx += x * x; sxy += x * y } }
              printf "%.6g", (k * sxy - sx * sy) / (k * sxx - sx * sx) }' "$tmp/s$U/trace.csv")
    l=$(linear $U)
    awk -v g="$g" -v l="$l" 'BEGIN { exit !(g * l > 0 && (g - l) ^ 2 < (0.1 * l) ^ 2) }' &&
        ok "at $U m/s: full-model growth $g 1/s, linear $l 1/s (same sign, within 10%)" ||
        bad "at $U m/s: full-model growth '$g' 1/s against linear '$l' 1/s"
done
finish
