# Re-parses the 50-trial power-kick table of the UT Austin Villa work log (10 Nov 2009, as
# stored) into rest distance and direction statistics: the source of
# models/kicks/aibo_ers7_published.json's forward kick (docs/sources/four_legged_figures.md).
import re, math, statistics as st, itertools
raw = """1-24382-162
2na85-11
3-340576
4na13484
51138391
6na139-50
7na10854
8na147-13
944398104
103224471
114520145
122635191
13na16621
14-182445
151124836
16-15202-15
17-40281-110
182420670
19-820416
20-55200-55
21na112-11
221623630
23na169-44
243020432
25023435
26-172361
27na842
28na9411
29-49212-78
30-17223-2
31na19237
32-106212-125
33na164-102
341824575
35225020
36-41217-16
37-54239-41
38-80225-127
39-29240-20
40022412
41na1338
421223-17
43na179-11
44na12129
450279-9
46-82172
47-37250-83
48-52204-79
49na19029
50-4210-1""".split()
# enumerate all splits: trial, y200 (na or int), X (int>0), Y (int); choose consistent
res=[]
for i,s in enumerate(raw, start=1):
    t=str(i); assert s.startswith(t); r=s[len(t):]
    cands=[]
    if r.startswith('na'):
        r2=r[2:]
        for k in range(1,len(r2)):
            X,Y=r2[:k],r2[k:]
            if re.fullmatch(r'[1-9]\d*',X) and re.fullmatch(r'-?(0|[1-9]\d*)',Y):
                X=int(X);Y=int(Y)
                if X<200 and abs(Y)<=X: cands.append((None,X,Y))
    else:
        for a in range(1,len(r)):
            for b in range(a+1,len(r)):
                y2,X,Y=r[:a],r[a:b],r[b:]
                if all(re.fullmatch(p,v) for p,v in [(r'-?(0|[1-9]\d*)',y2),(r'[1-9]\d*',X),(r'-?(0|[1-9]\d*)',Y)]):
                    y2=int(y2);X=int(X);Y=int(Y)
                    if X>=200 and X<=405 and abs(Y)<=X and abs(y2)<=200:
                        # consistency: y2 ~ Y*200/X
                        cands.append((y2,X,Y))
    if len(cands)>1:
        # pick one where y2 closest to straight-line interpolation
        def score(c):
            y2,X,Y=c
            return 0 if y2 is None else abs(y2 - Y*200/X)
        cands.sort(key=score)
    res.append((i,cands))
for i,c in res:
    print(i, c[:3])
sel=[c[0] for i,c in res]
X=[c[1] for c in sel]; Y=[c[2] for c in sel]
D=[math.hypot(x,y) for x,y in zip(X,Y)]
ang=[math.degrees(math.atan2(y,x)) for x,y in zip(X,Y)]
print('n',len(X),'mean X',st.mean(X),'sd X',st.stdev(X),'max X',max(X))
print('mean dist',st.mean(D),'sd',st.stdev(D),'max',max(D))
print('angle mean',st.mean(ang),'sd',st.stdev(ang))
reached=[c for c in sel if c[0] is not None]
print('reached 200cm',len(reached))
a200=[math.degrees(math.atan2(c[0],200)) for c in reached]
print('angle at 200 mean',st.mean(a200),'sd',st.stdev(a200), 'y200 sd', st.stdev([c[0] for c in reached]))
