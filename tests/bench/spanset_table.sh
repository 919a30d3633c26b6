#!/usr/bin/env bash
# spanset_table.sh: the tables of tests/bench/spanset.sh from what its OUT holds (acc/ the compare
# runs, spd/ the timed simulate runs): accuracy per span and mesh against issue 13's limits, speed
# per span and mesh, the medians over the set, how noisy the repeated timings are. Also written to
# OUT/table.md. Usage: tests/bench/spanset_table.sh [OUT]   (default out/spanset)
set -eu
out=${1:-out/spanset}
[ -d "$out/acc" ] || { echo "spanset_table.sh: $out/acc: nothing measured" >&2; exit 2; }
is_turbulent() { t=$(awk -F'=' '$1 ~ /^turbulence[ \t]*$/ { sub(/;.*/, "", $2); gsub(/[ \t]/, "", $2); print $2; exit }' "$1"); [ -n "$t" ] && [ "$t" != none ]; }
is_statistics() { awk '/^;/ { if (index($0, "statistics over perturbed runs")) y = 1; next } { exit } END { exit !y }' "$1"; }

# RMS about the mean of compare.csv's headline columns over [from, end]: 6 numbers
# (full v, reduced v, full h, reduced h, full twist, reduced twist)
rms_window() {
  awk -F, -v from="$2" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $1 >= from { n++; split("full_vertical_m reduced_vertical_m full_horizontal_m reduced_horizontal_m full_twist_deg reduced_twist_deg", k, " ")
      for (j = 1; j <= 6; j++) { x = $(c[k[j]]); s[j] += x; q[j] += x * x } }
    END { for (j = 1; j <= 6; j++) { m = s[j] / n; printf "%.6g ", sqrt(q[j] / n - m * m) } }' "$1"
}

# one line per compare run: span mesh stat rc ff fr vf vr hf hr tf tr Tf Tr res valid b0 b1 growths steady
rows() {
  for d in "$out"/acc/*/; do
    d=${d%/}; b=$(basename "$d"); tag=""
    case $b in *-warn) b=${b%-warn}; tag=w ;; esac
    span=${b%-e*}; rest=${b#"$span"-e}; mesh=${rest%-r*}$tag
    scene=tests/rom/$span.ini stat=0
    { is_turbulent "$scene" || is_statistics "$scene"; } && stat=1
    rc=$(cat "$d/rc" 2>/dev/null || echo -)
    if [ "$rc" != 0 ] || [ ! -s "$d/summary.json" ]; then echo "$span $mesh $stat ${rc:-?} FAIL"; continue; fi
    j="$d/summary.json"
    base=$(jq -r '[.full.frequency_hz, .reduced.frequency_hz, .full.amplitude_m.vertical, .reduced.amplitude_m.vertical,
      .full.amplitude_m.horizontal, .reduced.amplitude_m.horizontal, .full.twist_amplitude_deg, .reduced.twist_amplitude_deg,
      .full.tension_max_steady_n, .reduced.tension_max_steady_n] | map(tostring) | join(" ")' "$j")
    tail=$(jq -r '[.reduced.residual_max, (if .reduced.valid then 1 else 0 end), .reduced.basis_start, .reduced.basis,
      (.reduced.basis_growths | length), (if .full_window.steady then 1 else 0 end)] | map(tostring) | join(" ")' "$j")
    if [ $stat = 1 ]; then
      from=$(jq -r '[.steady_from_s, .duration_s / 2] | max' "$j")
      set -- $base $(rms_window "$d/compare.csv" "$from")
      base="$1 $2 ${11} ${12} ${13} ${14} ${15} ${16} $9 ${10}"
    fi
    echo "$span $mesh $stat $rc $base $tail"
    # the full statistics of a refused key: the runs that passed count in its on_invalid = warn row too
    [ -z "$tag" ] && echo "$span ${mesh}w $stat $rc $base $tail copy"
  done
}

acc_table() {
  rows | sort -k1,1 -k2,2n | awk '
    function rel(a, b) { return (a - b) / (b > 0 ? b : 1e-300) }
    function abs(x) { return x < 0 ? -x : x }
    $5 == "FAIL" { key = $1 " " $2; if (!(key in seen)) { seen[key] = 1; order[++nk] = key } fail[key] = $4; nf[key]++; next }
    { key = $1 " " $2; if (!(key in seen)) { seen[key] = 1; order[++nk] = key }
      if ($21 != "copy" && $2 ~ /w$/) realwarn[key] = 1
      n[key]++; st[key] = $3
      for (i = 5; i <= 14; i++) s[key, i] += $i
      if ($15 > res[key]) res[key] = $15
      if (!$16) invalid[key]++; b0[key] = $17; if ($18 > b1[key]) b1[key] = $18; gr[key] += $19
      if (!$20) unsteady[key]++ }
    END {
      print "| span | elements | runs | f Hz full/reduced | vertical m | horizontal m | twist deg | max support tension N | residual_max, valid, basis | issue 13 limits |"
      print "|---|---:|---|---|---|---|---|---|---|---|"
      for (q = 1; q <= nk; q++) {
        key = order[q]; split(key, kk, " ")
        if (kk[2] ~ /w$/ && !realwarn[key]) continue
        mesh = kk[2]; if (sub(/w$/, "", mesh)) mesh = mesh " (on_invalid = warn)"
        if (!(key in n)) { printf "| %s | %s | %d | | | | | | | **reduced model refused (exit %s) in %d of %d** |\n", kk[1], mesh, nf[key], fail[key], nf[key], nf[key]; nw++; continue }
        m = n[key]; for (i = 5; i <= 14; i++) v[i] = s[key, i] / m
        ef = abs(rel(v[6], v[5])); ev = abs(rel(v[8], v[7]))
        eh = abs(v[10] - v[9]) / (v[9] > 0.4 * v[7] ? v[9] : 0.4 * v[7]); et = abs(v[12] - v[11]); etr = abs(rel(v[12], v[11]))
        eT = abs(rel(v[14], v[13]))
        bad = ""
        if (ef > 0.01) bad = bad " f"; if (ev > 0.05) bad = bad " v"; if (eh > 0.05) bad = bad " h"
        if (et > 3 && etr > 0.05) bad = bad " twist"; if (eT > 0.05) bad = bad " T"
        verdict = bad == "" ? "within" : "**OUTSIDE:" bad "**"
        if (invalid[key]) verdict = verdict ", **valid false**"
        else if (bad != "") verdict = verdict " (valid: a silent miss)"
        if (realwarn[key]) verdict = verdict " (the runs that passed and the refused ones finished with on_invalid = warn)"
        if (nf[key]) verdict = verdict ", **reduced model refused (exit " fail[key] ") in " nf[key] " of " m + nf[key] " runs** (the rest shown)"
        if (unsteady[key]) verdict = verdict ", full not steady in " unsteady[key] " of " m
        what = st[key] ? sprintf("RMS, %d runs", m) : "p-p"
        hshow = v[9] > 0.4 * v[7] ? 100 * eh : 100 * abs(v[10] - v[9]) / v[7]; hnote = v[9] > 0.4 * v[7] ? "" : " of v"
        printf "| %s | %s | %s | %.4f/%.4f (%.2f%%) | %.3f/%.3f (%.1f%%) | %.3f/%.3f (%.1f%%%s) | %.1f/%.1f (%.1f, %.1f%%) | %.0f/%.0f (%.1f%%) | %.3f, %s, %d -> %d | %s |\n",
          kk[1], mesh, what, v[5], v[6], 100 * ef, v[7], v[8], 100 * ev, v[9], v[10], hshow, hnote,
          v[11], v[12], et, 100 * etr, v[13], v[14], 100 * eT, res[key], invalid[key] ? "false" : "true", b0[key], b1[key], verdict
        nw++; if (bad == "") nin++
      }
      printf "\nwithin the limits: %d of %d rows (a row: a span at a mesh; rows on_invalid = warn included)\n", nin, nw
    }'
}

# speed: one line per timed run: span mesh model T rep cpu rc
spd_rows() {
  for d in "$out"/spd/*/; do
    d=${d%/}; b=$(basename "$d")
    echo "$b" | sed -E 's/^(.*)-e([0-9]+)-(full|reduced)-t([0-9.]+)-r([0-9]+)$/\1 \2 \3 \4 \5/' | tr '\n' ' '
    [ -s "$d/rc" ] || { echo "running"; continue; }   # still running: left out
    tail -n 1 "$d/time" | awk '{ printf "%.2f ", $1 + $2 }'
    cat "$d/rc"
  done | grep -v ' running$'

}

spd_table() {
  spd_rows | sort -k1,1 -k2,2n | awk '
    function med(a, n,   i, j, t) { for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] > a[j]; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
      return n % 2 ? a[(n + 1) / 2] : 0.5 * (a[n / 2] + a[n / 2 + 1]) }
    { key = $1 " " $2; if (!(key in seen)) { seen[key] = 1; order[++nk] = key }
      if ($4 > T) T = $4; if ($4 > Tk[key]) Tk[key] = $4
      if ($7 != 0) { failed[key] = failed[key] " " $3 "(" $4 " s) exit " $7; next }
      c = ++cnt[key, $3, $4]; cpu[key, $3, $4, c] = $6; rep[key, $3, $4, $5] = $6; nrep[key] = $5 > nrep[key] ? $5 : nrep[key] }
    END {
      print "| span | elements | full CPU s, whole " T "-s run | reduced | whole process x | full CPU s per simulated s | reduced | per simulated s x |"
      print "|---|---:|---:|---:|---:|---:|---:|---:|"
      for (q = 1; q <= nk; q++) {
        key = order[q]; split(key, kk, " "); T1 = Tk[key]
        if (key in failed) { printf "| %s | %s | | | | | | FAILED:%s |\n", kk[1], kk[2], failed[key]; continue }
        split("full reduced", M, " "); incomplete = 0
        for (mm = 1; mm <= 2; mm++) for (t = 0; t <= 1; t++) {
          tt = t ? T1 : 10; n = cnt[key, M[mm], tt]; delete a; if (!n) incomplete = 1
          for (i = 1; i <= n; i++) a[i] = cpu[key, M[mm], tt, i]
          x[mm, t] = med(a, n)
        }
        if (incomplete) { printf "| %s | %s | | | | | | not all measured yet |\n", kk[1], kk[2]; continue }
        pf = (x[1, 1] - x[1, 0]) / (T1 - 10); pr = (x[2, 1] - x[2, 0]) / (T1 - 10)
        w = x[1, 1] / x[2, 1]; p = pf / pr
        printf "| %s | %s | %.2f | %.2f | %.1f%s | %.4f | %.5f | %.1f |\n", kk[1], kk[2], x[1, 1], x[2, 1], w, T1 != T ? " (" T1 "-s run)" : "", pf, pr, p
        nw[kk[2]]++; W[kk[2], nw[kk[2]]] = w; P[kk[2], nw[kk[2]]] = p
        if (nrep[key] > 1) {   # the repeats: each repeat own ratios
          line = ""; delete rw; delete rp
          for (r = 1; r <= nrep[key]; r++) {
            rw[r] = rep[key, "full", T1, r] / rep[key, "reduced", T1, r]
            rp[r] = (rep[key, "full", T1, r] - rep[key, "full", 10, r]) / (rep[key, "reduced", T1, r] - rep[key, "reduced", 10, r])
            line = line sprintf(" %.1f/%.1f", rw[r], rp[r])
          }
          lo = rw[1]; hi = rw[1]; lp = rp[1]; hp = rp[1]
          for (r = 2; r <= nrep[key]; r++) { if (rw[r] < lo) lo = rw[r]; if (rw[r] > hi) hi = rw[r]; if (rp[r] < lp) lp = rp[r]; if (rp[r] > hp) hp = rp[r] }
          noise = noise sprintf("- %s at %s elements, %d repeats, whole/per-simulated-s x:%s; spread (max-min)/median %.0f%% and %.0f%%\n",
            kk[1], kk[2], nrep[key], line, 100 * (hi - lo) / med(rw, nrep[key]), 100 * (hp - lp) / med(rp, nrep[key]))
        }
      }
      print ""
      for (e = 0; e < 3; e++) {
        mesh = e == 0 ? 100 : e == 1 ? 125 : 400; n = nw[mesh]; if (!n) continue
        delete a; for (i = 1; i <= n; i++) a[i] = W[mesh, i]; mw = med(a, n)
        delete a; for (i = 1; i <= n; i++) a[i] = P[mesh, i]; mp = med(a, n)
        printf "median over %d spans at %d elements: whole process %.1fx (issue: %s), per simulated second %.1fx (issue: >= %s)\n",
          n, mesh, mw, mesh == 400 ? "no target at 400" : ">= 10x", mp, mesh == 400 ? "100x" : "30x"
      }
      printf "(medians over the spans whose runs all finished; FAILED rows are left out)\n"
      if (noise != "") printf "\nnoise (CPU time, repeated runs):\n%s", noise
    }'
}

{
  echo "## accuracy (gallop compare; reduced/full, error)"
  echo
  [ -s "$out/meta" ] && sed 's/^/    /' "$out/meta" && echo
  acc_table
  echo
  echo "## speed (gallop simulate, CPU user+sys of each process)"
  echo
  spd_table
} | tee "$out/table.md"
