#!/usr/bin/env python3
"""Independent arithmetic behind the hand checks of tests/prime/golden/README.md.

Nothing here uses the port's code: rays, intersections, the listing's rotation (Radient
57.29578), GetUVSphere, ReadMap, Hall's sum and ColorNum are written out again from the
listing and the errata. Each check prints the colour and index worked out here next to what
`prime probe` says for the same pixel of the golden render (--screen 512 384).

Usage: tests/prime/golden/hand_checks.py PRIME_EXE   (from the repository root; models copies of
the scenes in a temporary directory).
"""
import math
EYE=(500.0,500.0,-1500.0)
def sub(a,b): return tuple(x-y for x,y in zip(a,b))
def add(a,b): return tuple(x+y for x,y in zip(a,b))
def mul(a,s): return tuple(x*s for x in a)
def dot(a,b): return sum(x*y for x,y in zip(a,b))
def unit(a): l=math.sqrt(dot(a,a)); return mul(a,1/l)
def ray(j,i,W=512,H=384,xmin=0.66):
    left=int(xmin*W); na=W-left; nd=H
    wx=j*1000.0/na; wy=1000.0-i*1000.0/nd
    return unit(sub((wx,wy,0.0),EYE)), (wx,wy)
def sphere(d,c,r,o=EYE):
    oc=sub(o,c); b=dot(oc,d); cc=dot(oc,oc)-r*r; disc=b*b-cc
    if disc<0: return None
    t=-b-math.sqrt(disc); p=add(o,mul(d,t)); return t,p,unit(sub(p,c))
def plane(d,axis,val,o=EYE):
    t=(val-o[axis])/d[axis]; return t, add(o,mul(d,t))
def fsr(f0,iL,cosang):
    if f0==0: return 0.0
    tmp=(cosang*f0-f0)/(0-f0)
    return iL*(f0+(1-f0)*tmp) if tmp>=0 else iL*f0
def hall(pt,v,n,lights,IA,hue,tex,iSR=(0,0,0),iST=(0,0,0),r=None,sT=0.0):
    kDR,kDT,fDR,tT,kRH,kTH,indx=hue
    out=[]
    for lam in range(3):
        a=b=c=d=0.0
        for (lp,I) in lights:
            l=unit(sub(pt,lp)); h=unit(add(l,v)); dh=dot(n,h)
            hp=unit(mul(add(v,mul(l,indx)),1/(indx-1))); dh_=dot(n,hp)
            iL=I[lam]
            a+=iL*fsr(tex[lam],iL,dh)*dh**kRH
            b+=iL*(1-fsr(tex[lam],iL,dh_))*dh_**kTH
            vD=dot(n,l); c+=iL*vD; d+=iL*-vD
        col=(1-kDR)*a+(1-kDT)*b+kDR*fDR[lam]*(IA[lam]+c)+kDT*(1-fDR[lam])*(IA[lam]+d)
        if r is not None: col+=(1-kDR)*iSR[lam]*fsr(tex[lam],IA[lam],dot(n,r))
        col+=(1-kDT)*iST[lam]*(1-fsr(tex[lam],IA[lam],1.0))*tT**sT
        out.append(min(col,0.999999) if col>=1 else col)
    return out
def colornum(c):
    r=math.floor(c[0]*7); g=math.floor(c[1]*7); b=math.floor(c[2]*3); v=r*32+g*4+b
    return v if v!=0 else 1
def plate3(c):
    v=16*math.floor(c[0]*15)+math.floor(c[1]*15); return v if v!=0 else 1
RAD=57.29578
def rotm(rx,ry,rz):
    # rows = images of the unit vectors under p*Rx*Ry*Rz (row vectors, listing order)
    def rot(p):
        x,y,z=p
        c,s=math.cos(rx/RAD),math.sin(rx/RAD); y,z=y*c-z*s, z*c+y*s
        c,s=math.cos(ry/RAD),math.sin(ry/RAD); x,z=x*c+z*s, z*c-x*s
        c,s=math.cos(rz/RAD),math.sin(rz/RAD); x,y=x*c-y*s, y*c+x*s
        return (x,y,z)
    return [rot((1,0,0)),rot((0,1,0)),rot((0,0,1))]
def vm(p,M): return tuple(sum(p[k]*M[k][j] for k in range(3)) for j in range(3))
def vmT(p,M): return tuple(sum(p[k]*M[j][k] for k in range(3)) for j in range(3))
def tolocal(w,s,t,r,pv):
    M=rotm(*r); q=vmT(sub(w,t),M)   # R orthonormal: inverse = transpose
    return tuple(q[k]/s[k]+pv[k] for k in range(3))
def dirlocal(d,s,r):
    M=rotm(*r); q=vmT(d,M); return tuple(q[k]/s[k] for k in range(3))
def box(d,s,t,r,pv,o=EYE):
    # slab test in local [0,1]^3; t is the world parameter (direction not renormalised)
    lo=tolocal(o,s,t,r,pv); ld=dirlocal(d,s,r); t0,t1=-1e300,1e300; n0=n1=None
    for k in range(3):
        if ld[k]==0: continue
        a=(0-lo[k])/ld[k]; b=(1-lo[k])/ld[k]
        na=tuple(-1 if j==k else 0 for j in range(3)); nb=tuple(1 if j==k else 0 for j in range(3))
        if a>b: a,b,na,nb=b,a,nb,na
        if a>t0: t0,n0=a,na
        if b<t1: t1,n1=b,nb
    if t0>t1 or t1<0: return None
    p=add(o,mul(d,t0)); lp=add(lo,mul(ld,t0))
    M=rotm(*r); nw=unit(vm(tuple(n0[k]*s[k] for k in range(3)),M))  # K4: forward 3x3 (S*R)
    return t0,p,lp,nw,t1
def readmap(path):
    w=open(path).read().split(); m=int(w[0]); u=int(w[1]); v=int(w[2]); vals=[float(x) for x in w[3:]]
    n=u*v; return u,v,[vals[0:n],vals[n:2*n],vals[2*n:3*n]]
def texel(mp,u,v):
    us,vs,pl=mp; iu=int(u*us); iv=int(v*vs); iu=max(iu,0); k=iu+us*iv
    if k<0: k=0
    if k>=us*vs: return (0.0,0.0,0.0),k
    return tuple(pl[c][k] for c in range(3)),k
PIINV=0.318309886
def uvsphere(n):
    alpha=math.acos(-n[2]); v=alpha*PIINV
    if v==0 or v==1: return 0.0,v
    beta=math.acos(max(-1,min(1,n[0]/math.sin(alpha))))*PIINV
    return (beta if n[1]>0 else 1-beta), v
import subprocess,re
import sys, os, shutil, tempfile
PRIME=sys.argv[1] if len(sys.argv)>1 else 'build/release/src/cli/prime'
TMP=tempfile.mkdtemp(prefix='prime-hand-')
def scene(name):
    d=os.path.join(TMP,name)
    if not os.path.exists(d):
        shutil.copytree(os.path.join('scenes','prime',name),d,ignore=shutil.ignore_patterns('PrimFile','O[0-9]*','List','*.map','graph_scr','*.png'))
        subprocess.run([PRIME,'model',d],check=True,capture_output=True)
    return d
def probe(scene,j,i,extra=()):
    out=subprocess.run([PRIME,'probe',scene,'--screen','512','384','--pixel',str(j),str(i),*extra],capture_output=True,text=True).stdout
    m=re.search(r'palette index (-?\d+)',out); return int(m.group(1)), out
import struct
def golden(scenedir,j,i):
    g=open(os.path.join('tests','golden','prime',os.path.basename(scenedir),'graph_scr'),'rb').read()
    w=struct.unpack('<h',g[2:4])[0]+1
    return struct.unpack('<h',g[6+2*(i*w+j):8+2*(i*w+j)])[0]
def report(name,j,i,col,idx,scene,extra=(),t=None):
    pidx,out=probe(scene,j,i,extra)
    gidx=golden(scene,j,i)
    m=re.search(r'^  hit: nearest: .* at t ([0-9.e+-]+),',out,re.M)
    pt=float(m.group(1)) if m else None
    ts=''
    if t is not None: ts=f' t {t:.3f} (probe {pt})'
    ok=idx==pidx==gidx and (t is None or (pt is not None and abs(pt-t)<1e-3*max(1,abs(t))))
    print(f'{name}: pixel ({j},{i}){ts} hand colour ({col[0]:.6f}, {col[1]:.6f}, {col[2]:.6f}) -> index {idx}; prime probe {pidx}, golden {gidx}  {"OK" if ok else "MISMATCH"}')
    return out

# ======== checks1.py
# ---- lights: middle sphere (Lambert via diffuse transmission), left sphere (K10), background
L=[((-1000,500,-800),(0.45,0,0)),((2000,500,-800),(0,0.45,0)),((500,-1500,-1000),(0,0,0.6)),((500,2500,-500),(0.25,0.25,0.25))]
IA=(0.5,0.5,0.5)
d,w=ray(88,192); t,p,n=sphere(d,(500,500,300),140)
c=hall(p,d,n,L,IA,(0.0,1.0,(0,0,0),0.999,0,0,1.0001),(0,0,0)); report('lights middle sphere',88,192,c,colornum(c),scene('lights'),t=t)
d,w=ray(26,180); t,p,n=sphere(d,(180,500,300),140)
c=hall(p,d,n,L,IA,(1.0,1.0,(1,1,1),0.999,0,0,1.0001),(0,0,0)); report('lights left sphere (K10)',26,180,c,colornum(c),scene('lights'),t=t)
report('lights background',0,0,(0,0,0),colornum((0,0,0)),scene('lights'))
# ---- primitives: the sphere (bound cube), checker map, three lights
L=[((-500,1500,-1000),(0.4,0.4,0.4)),((1500,1500,-1000),(0.35,0.35,0.35)),((500,-800,-800),(0.25,0.25,0.25))]
mp=readmap(scene('primitives')+'/map/Map1.txt')
for (j,i) in [(38,94),(30,100)]:
    d,w=ray(j,i); t,p,n=sphere(d,(230,760,300),130); u,v=uvsphere(n); tx,k=texel(mp,u,v)
    r=unit(sub(d,mul(n,2*dot(d,n))))
    c=hall(p,d,n,L,(0.2,0.2,0.2),(0.0,1.0,(0.75,0.75,0.75),0.999,0,0,1.0001),tx,r=r)
    out=report(f'primitives sphere (u {u:.4f} v {v:.4f} texel {k})',j,i,c,colornum(c),scene('primitives'),t=t)
report('primitives background',175,384,(0,0,0),colornum((0,0,0)),scene('primitives'))

# ======== checks2.py
L1=[((300,1500,-1500),(0.6,0.6,0.6))]
H=(0.0,1.0,(0.75,0.75,0.75),0.999,0,0,1.0001)
# ---- csg-operators: the union's cube front face (B1: centre (200,670,300), 170, pivot .5)
for (j,i) in [(30,150),(45,140)]:
    d,w=ray(j,i); h=box(d,(170,170,170),(200,670,300),(0,0,0),(.5,.5,.5)); t0,p,lp,n,t1=h
    s=sphere(d,(300,790,300),110)
    mp=readmap(scene('csg-operators')+'/map/Map2.txt'); tx,k=texel(mp,lp[0],1-lp[1])
    c=hall(p,d,n,L1,(0.2,0.2,0.2),H,tx)
    report(f'csg union cube face (local {lp[0]:.3f},{lp[1]:.3f},{lp[2]:.3f}; sphere {"missed" if s is None else "behind at t %.1f"%s[0]})',j,i,c,colornum(c),scene('csg-operators'),t=t0)
# ---- copies: the O-entry copy of S1 through A1: radius 70 at d*s = (4.5,8,3)*100
d,w=ray(80,96); t,p,n=sphere(d,(450,800,300),70)
c=hall(p,d,n,L1,(0.2,0.2,0.2),H,(0.02,0.02,0.02)); report('copies O-entry copy of S1 (centre (450,800,300) r 70)',80,96,c,colornum(c),scene('copies'),t=t)
# the copy of S2 through A2: radius 50 at (8,7.5,3)*60 = (480,450,180)
d,w=ray(87,203); t,p,n=sphere(d,(480,450,180),50)
c=hall(p,d,n,L1,(0.2,0.2,0.2),H,(0,0.02,0)); report('copies O-entry copy of S2 (centre (480,450,180) r 50)',87,203,c,colornum(c),scene('copies'),t=t)
# ---- glass: the wall's z=0 face at z=900, stripes map
Lg=[((500,1500,-1500),(0.5,0.5,0.5))]
mp=readmap(scene('glass')+'/map/Map1.txt')
for (j,i) in [(5,5),(170,380)]:
    d,w=ray(j,i); h=box(d,(1700,1700,20),(-350,-350,900),(0,0,0),(0,0,0)); t0,p,lp,n,t1=h
    tx,k=texel(mp,lp[0],1-lp[1])
    c=hall(p,d,n,Lg,(0.3,0.3,0.3),H,tx)
    report(f'glass wall (texel {k})',j,i,c,colornum(c),scene('glass'),t=t0)

# ======== checks3.py
L1=[((500,1500,-1500),(0.6,0.6,0.6))]
H=(0.0,1.0,(0.75,0.75,0.75),0.999,0,0,1.0001)
# ---- map-edge: the right face of pyramid 2 (S1: the printed polygon), E51
S=(400,500,400); T=(740,200,300); R=(0,80,0); PV=(0.5,0,0.5)
def rightface(j,i):
    d,w=ray(j,i); lo=tolocal(EYE,S,T,R,PV); ld=dirlocal(d,S,R)
    # plane x + y/2 = 1
    t=(1-lo[0]-lo[1]/2)/(ld[0]+ld[1]/2); lp=add(lo,mul(ld,t))
    x,y,z=lp
    if not (y>=0 and y/2<=z<=1-y/2): return None
    u=1.25*(z-y/2)/(z-0.5); return d,t,lp,u
found=None
for i in range(150,300):
    for j in range(110,175):
        r=rightface(j,i)
        if r and 0.5<r[2][2]<0.5625 and r[3]>=8.5: found=(j,i); break
    if found: break
j,i=found; d,t,lp,u=rightface(j,i)
M=rotm(*R); n=unit(vm((1*S[0],0.5*S[1],0),M))
p=add(EYE,mul(d,t))
c=hall(p,d,n,L1,(0.2,0.2,0.2),H,(0,0,0))
report(f'map-edge right face (local {lp[0]:.4f},{lp[1]:.4f},{lp[2]:.4f}: u {u:.3f} -> newU {int(u*8)}, newV 0 -> texel {int(u*8)} >= 64: E51, 0.0)',j,i,c,colornum(c),scene('map-edge'),t=t)
# same face, z < 0.5: u <= 0 -> column 0 (clamped), row trunc(8(1-2z))
cand=[(j,i) for i in range(200,330,4) for j in range(110,176,2) if rightface(j,i) and rightface(j,i)[2][2]<0.45]
for (j,i) in cand[len(cand)//2:len(cand)//2+1]:
    r=rightface(j,i); d,t,lp,u=r; v=1-2*lp[2]
    mp=readmap(scene('map-edge')+'/map/Map1.txt'); tx,k=texel(mp,u,v)
    p=add(EYE,mul(d,t))
    c=hall(p,d,n,L1,(0.2,0.2,0.2),H,tx)
    report(f'map-edge right face (z {lp[2]:.4f} < 0.5: u {u:.3f} -> 0, v {v:.3f} -> texel {k})',j,i,c,colornum(c),scene('map-edge'),t=t)
# ---- inside-maps: the open box's front face, outer cube B3 rotated -25 about X; K31 normal
S3=(420,180,400); T3=(270,60,450); R3=(-25,0,0); P3=(0.5,0,0.5)
S4=(390,180,370); P4=(0.5,-0.111111,0.5)
mp=readmap(scene('inside-maps')+'/map/Map1.txt')
for (j,i) in [(30,330)]:
    d,w=ray(j,i); t0,p,lp,n,t1=box(d,S3,T3,R3,P3); hi=box(d,S4,T3,R3,P4)
    tx,k=texel(mp,lp[0],1-lp[1])
    c=hall(p,d,hi[3],L1,(0.2,0.2,0.2),H,tx)
    report(f'inside-maps box front (outer local {lp[0]:.3f},{lp[1]:.3f},{lp[2]:.3f}, texel {k}; ray enters the inner box at local z {hi[2][2]:.3f}, t {hi[0]:.2f}: K31 takes its normal)',j,i,c,colornum(c),scene('inside-maps'),t=t0)

# ======== checks4.py
# ---- default: the glass sphere (H2: kDR 0, kDT 0, kRH kTH 3, indx 1.5), map 3; both secondary rays miss
d,w=ray(117,150); t,p,n=sphere(d,(700,650,300),150)
c=hall(p,d,n,[((500,1500,-1000),(0.8,0.8,0.8))],(0.2,0.2,0.2),(0.0,0.0,(0.2,0.3,0.6),0.999,3,3,1.5),(0.3,0.5,0.9))
report('default glass sphere (odd kRH: negative highlight, K10/K15)',117,150,c,colornum(c),scene('default'),t=t)
report('default background',0,384,(0,0,0),colornum((0,0,0)),scene('default'))
# ---- plate2: the bottom-left box's front face and the D.C.U. lettering (cube turned -20, 35)
L=[((500,900,-1500),(0.6,0.6,0.6))]; H=(0.0,1.0,(0.75,0.75,0.75),0.999,0,0,1.0001)
d,w=ray(30,330); t0,p,lp,n,t1=box(d,(300,240,300),(80,60,200),(0,0,0),(0,0,0))
tx,k=texel(readmap('scenes/prime/plate2/map/Map6.txt'),lp[0],1-lp[1])
c=hall(p,d,n,L,(0.2,0.2,0.2),H,tx); report('plate2 5.3.2 object, B1 front face',30,330,c,colornum(c),scene('plate2'),t=t0)
S=(400,400,400);T=(720,280,250);R=(-20,35,0);PV=(.5,.5,.5)
d,w=ray(111,239); t0,p,lp,n,t1=box(d,S,T,R,PV); hi=box(d,(350,350,350),T,R,PV)
tx,k=texel(readmap('scenes/prime/plate2/map/Map4.txt'),lp[0],1-lp[1])
c=hall(p,d,hi[3],L,(0.2,0.2,0.2),H,tx)
report(f'plate2 D.C.U. cube front face, ink texel {k} (column {k%39}, row {k//39})',111,239,c,colornum(c),scene('plate2'),t=t0)
# ---- plate3: the chessboard (non-uniform scale, turned -12 about X), yellow light, plate 3 mapping
mp=readmap(scene('plate3')+'/map/Map1.txt')
for (j,i) in [(20,360),(150,330)]:
    d,w=ray(j,i); t0,p,lp,n,t1=box(d,(1400,30,1400),(-200,60,-100),(-12,0,0),(0,0,0))
    tx,k=texel(mp,lp[0],1-lp[2])
    r=unit(sub(d,mul(n,2*dot(d,n))))
    sp=sphere(r,(500,420,700),170,o=add(p,r))
    c=hall(p,d,n,[((200,1500,-500),(0.6,0.6,0))],(0.5,0.5,0),(0.0,1.0,(0.85,0.85,0.85),0.999,0,0,1.0001),tx,r=r)
    report(f'plate3 board top (local {lp[0]:.3f},{lp[1]:.3f},{lp[2]:.3f}, square {k}; reflection {"misses" if sp is None else "HITS"} the sphere)',j,i,c,plate3(c),scene('plate3'),extra=('--palette','plate3'),t=t0)
report('plate3 background',88,20,(0,0,0),plate3((0,0,0)),scene('plate3'),extra=('--palette','plate3'))

# ======== plate1
# plate1: surface points of the 8 x 8 knots (beta1 = beta2 = 1) projected by hand onto the
# golden's screen (512 x 384, viewport 0.66..1: left 337, 175 x 384 steps)
import math
w=open('scenes/prime/plate1/knots.txt').read().split()
V=[[tuple(float(w[4+3*(8*r+c)+k]) for k in range(3)) for c in range(8)] for r in range(8)]
def basis(u):  # beta1 = beta2 = 1, delta = 13
    return [2*(1-u)**3/13,
            (2*u*(u*u-3*u+3)+2*(u**3-3*u*u+2)+2*(u**3-3*u+2)+(2*u**3-3*u*u+1))/13,
            (2*u*u*(3-u)+2*u*(3-u*u)+u*u*(3-2*u)+2*(1-u**3))/13,
            2*u**3/13]
def S(U,Vv):
    pc=min(int(U),4); pr=min(int(Vv),4); bu=basis(U-pc); bv=basis(Vv-pr)
    return tuple(sum(bv[r]*bu[c]*V[pr+r][pc+c][k] for r in range(4) for c in range(4)) for k in range(3))
def proj(p):
    e=(500,500,-1500); t=(0-e[2])/(p[2]-e[2]); wx=e[0]+(p[0]-e[0])*t; wy=e[1]+(p[1]-e[1])*t
    sx=337+wx*175/1000; sy=(1000-wy)*384/1000
    return (round(sx+1e-12)-337, round(sy+1e-12)), (wx,wy), (sx,sy)  # lround: halves away from zero (all positive here)
g=open('tests/prime/golden/plate1/graph_scr','rb').read()
import struct
ga,gd=struct.unpack('<hh',g[2:6]); W=ga+1
def pix(x,y): return struct.unpack('<h',g[6+2*(y*W+x):8+2*(y*W+x)])[0]
for (U,Vv,want,why) in [(0,0,2,'corner: the U = 0 curve (red, drawn after the V curves) ends here'),
                        (0.375,0,5,'on the V = 0 curve (yellow) between two red curves'),
                        (5,5,2,'far corner')]:
    p=S(U,Vv); (x,y),wwin,s=proj(p)
    print(f'plate1 S(U={U},V={Vv}) = ({p[0]:.3f}, {p[1]:.3f}, {p[2]:.3f}) -> window ({wwin[0]:.3f}, {wwin[1]:.3f}) -> screen ({s[0]:.3f}, {s[1]:.3f}) -> graph ({x},{y}): golden {pix(x,y)}, expected {want} ({why}) {"OK" if pix(x,y)==want else "MISMATCH"}')
print('plate1 background (0,0):', pix(0,0))

shutil.rmtree(TMP)
