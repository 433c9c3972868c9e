# writes legs.in: the fix move sequence of the bending path (see energy_bendcycle.in)
import sys, math
a,b,w,dt,ncyc,d=float(sys.argv[1]),float(sys.argv[2]),float(sys.argv[3]),float(sys.argv[4]),int(sys.argv[5]),int(sys.argv[6])
P=2*math.pi/w
legs=[('+y',a,'setup'),('-y',a,'setup')]
sq=[('+y',b),('+z',b),('-y',2*b),('-z',b),('+y',b)]
if d<0: sq=[('-y',b),('+z',b),('+y',2*b),('-z',b),('-y',b)]   # mirror: (0,0)->(-b,0)->(-b,b)->(b,b)->(b,0)->(0,0)
for c in range(ncyc):
    for ax,ang in sq: legs.append((ax,ang,'cycle%d'%(c+1)))
axes={'+y':'0 1 0','-y':'0 -1 0','+z':'0 0 1','-z':'0 0 -1'}
out=[]
for i,(ax,ang,tag) in enumerate(legs):
    n=round(ang/(w*dt))
    out.append(f'fix mv drv move rotate 0.001 0 0 {axes[ax]} {P!r}')
    out.append(f'run {n}')
    out.append('unfix mv')
    out.append(f'print "LEG {i} {tag} {ax} {n}"')
open('legs.in','w').write('\n'.join(out)+'\n')
