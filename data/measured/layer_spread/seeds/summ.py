import csv, json, glob, os, statistics as st
os.chdir(os.path.dirname(os.path.abspath(__file__)))
print(f"{'kind':4} {'seed':4} {'poros':6} {'H':>3} {'share':>5} {'pen_rm':>12} {'loss1':>6} {'e_n':>6}")
for kind in ['A','a1']:
    for seed in [1,2,3,4]:
        f=f'{kind}_seed{seed}.csv'
        if not os.path.exists(f): continue
        mk=json.load(open(f'make_{kind}_seed{seed}.json'))
        rows=list(csv.DictReader(l for l in open(f) if not l.startswith('#')))
        for H in (8,16):
            rr=[r for r in rows if float(r['height-rm'])==H]
            b=[int(r['bounced']) for r in rr]; p=[float(r['penetration_rm']) for r in rr]; l=[float(r['block_loss_first_contact']) for r in rr]
            en=[float(r['e_n']) for r in rr if r['bounced']=='1']
            print(f"{kind:4} {seed:4} {mk['porosity']:.3f} {H:3} {sum(b)/len(b):5.2f} {st.mean(p):5.2f}+-{st.pstdev(p):.2f} {st.mean(l):6.2f} {st.mean(en) if en else float('nan'):6.3f}")
