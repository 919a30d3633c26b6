"""weight_table.py OUT TAG...: the table of tests/bench/weight.sh from OUT/TAG/CASE/summary.json."""
import json,sys,os,glob
base=sys.argv[1]
tags=sys.argv[2:]
cases=sorted(set(os.path.basename(p) for t in tags for p in glob.glob(os.path.join(base,t,'*'))))
print("| case | variant | f % | v % | h % | twist % | Tmax % | residual_max | basis | valid | reduced wall s |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for c in cases:
  for t in tags:
    p=os.path.join(base,t,c,'summary.json')
    if not os.path.exists(p): continue
    try: j=json.load(open(p))
    except Exception as e: print(c,t,'bad',e); continue
    f=j['full']; r=j['reduced']; a=j['amplitude_errors']
    sgn=lambda x,y: 100*(x-y)/y
    fe=sgn(r['frequency_hz'],f['frequency_hz'])
    ve=sgn(r['amplitude_m']['vertical'],f['amplitude_m']['vertical'])
    he=sgn(r['amplitude_m']['horizontal'],f['amplitude_m']['horizontal'])
    te=sgn(r['twist_amplitude_deg'],f['twist_amplitude_deg'])
    Te=sgn(r['tension_max_n'],f['tension_max_n'])
    print("| %s | %s | %+.2f | %+.2f | %+.2f | %+.2f | %+.2f | %.3g | %d->%d | %s | %.2f |"%(c,t,fe,ve,he,te,Te,r['residual_max'],r['basis_start'],r['basis'],r['valid'],r['wall_time_s']))
