"""compare_windows.py DIR/compare.csv [FROM_S] [WIDTH_S]: the peak-to-peak of the full and the reduced
run (full/reduced) in consecutive windows of WIDTH_S (default 40 s) from FROM_S (default 0): mid-span
vertical, quarter-span vertical, mid-span horizontal and twist, from the probe columns of `gallop
compare` (probes 0.5 and 0.25). Shows when each run leaves an orbit, which one window's figure hides
(BENCHMARKS.md, "The 40-element soft-torsion miss", helper forty, session 11)."""
import csv, sys

rows = list(csv.DictReader(open(sys.argv[1])))
a = float(sys.argv[2]) if len(sys.argv) > 2 else 0.0
width = float(sys.argv[3]) if len(sys.argv) > 3 else 40.0
cols = [('v0.5', 'p0.5_vertical_m'), ('v0.25', 'p0.25_vertical_m'), ('h0.5', 'p0.5_horizontal_m'),
        ('t0.5', 'p0.5_twist_deg')]
end = float(rows[-1]['time_s'])
while a < end:
    b = a + width
    sel = [x for x in rows if a <= float(x['time_s']) < b]
    out = []
    for name, col in cols:
        pp = []
        for model in ('full', 'reduced'):
            v = [float(x[model + '_' + col]) for x in sel]
            pp.append(max(v) - min(v))
        out.append('%s %.3f/%.3f' % (name, pp[0], pp[1]))
    print('%5.0f-%5.0f  %s' % (a, b, '  '.join(out)))
    a = b
