# Two bonded spheres (R = 1 mm, rb = 1 mm); sphere 1 frozen, sphere 2 spun
# about the oblique axis (1, 0.6, 0.3) through its centre for 2000 steps,
# then free: twisting and bending about every coordinate axis, their
# loading, unloading and reverse branches on both sides, the shear the
# spin drags, percentage damping on every law. Prints sphere 2 every 50 steps.
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box
create_box 1 box
neighbor 0.0002 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 1.e7
fix m2 all property/global poissonsRatio peratomtype 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
fix b1 all property/global radiusMultiplierBondnonlinear peratomtypepair 1 1.0
fix b2 all property/global tsCreateBondnonlinear scalar 1
fix b3 all property/global createDistanceBondnonlinear peratomtypepair 1 2.1e-3
fix b4 all property/global maxDistanceBondnonlinear peratomtypepair 1 3.0e-3
fix b5 all property/global stiffnessPerUnitAreaK_fn1 peratomtypepair 1 1.0e2
fix b6 all property/global stiffnessPerUnitAreaKu_fn1 peratomtypepair 1 2.0e2
fix b7 all property/global stiffnessPerUnitAreaKc_fn1 peratomtypepair 1 0.5e2
fix b8 all property/global stiffnessPerUnitAreaK_fn2 peratomtypepair 1 1.0e11
fix b9 all property/global stiffnessPerUnitAreaKu_fn2 peratomtypepair 1 2.0e11
fix b10 all property/global stiffnessPerUnitAreaKc_fn2 peratomtypepair 1 5.0e10
fix b11 all property/global stiffnessPerUnitAreaK_ft peratomtypepair 1 4.0e11
fix b12 all property/global stiffnessPerUnitAreaK_tn peratomtypepair 1 4.0e8
fix b13 all property/global stiffnessPerUnitAreaKu_tn peratomtypepair 1 8.0e8
fix b14 all property/global stiffnessPerUnitAreaKc_tn peratomtypepair 1 2.0e8
fix b15 all property/global stiffnessPerUnitAreaK_tt peratomtypepair 1 4.0e8
fix b16 all property/global stiffnessPerUnitAreaKu_tt peratomtypepair 1 8.0e8
fix b17 all property/global stiffnessPerUnitAreaKc_tt peratomtypepair 1 2.0e8
fix b18 all property/global dampingNormalForceBondnonlinear peratomtypepair 1 0.1
fix b19 all property/global dampingTangentialForceBondnonlinear peratomtypepair 1 0.1
fix b20 all property/global dampingNormalTorqueBondnonlinear peratomtypepair 1 0.1
fix b21 all property/global dampingTangentialTorqueBondnonlinear peratomtypepair 1 0.1
pair_style gran model hertz tangential history cohesion bond/nonlinear
pair_coeff * *
create_atoms 1 single 0 0 0 units box
create_atoms 1 single 0.002 0 0 units box
set atom * diameter 0.002 density 2500
group g1 id 1
group g2 id 2
fix f1 g1 freeze
timestep 1.0e-7
variable t equal time
variable x2 equal x[2]
variable y2 equal y[2]
variable z2 equal z[2]
variable wx equal omegax[2]
variable wy equal omegay[2]
variable wz equal omegaz[2]
variable tx equal tqx[2]
variable ty equal tqy[2]
variable tz equal tqz[2]
variable fx2 equal fx[2]
variable fy2 equal fy[2]
variable fz2 equal fz[2]
fix out all print 50 "${t} ${x2} ${y2} ${z2} ${wx} ${wy} ${wz} ${tx} ${ty} ${tz} ${fx2} ${fy2} ${fz2}" file spin.txt screen no title "t x2 y2 z2 wx2 wy2 wz2 tqx2 tqy2 tqz2 fx2 fy2 fz2"
thermo 1000
fix spin g2 move rotate 0.002 0 0 1 0.6 0.3 1.0
run 2000
unfix spin
fix nve g2 nve/sphere
run 18000
