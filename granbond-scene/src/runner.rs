//! The scene: spheres, bonds, contacts, planes, and one time step.

use super::cells::close_pairs;
use granbond::bond::{BondModel, BondOutput, BondState, BondStatus, BreakMode};
use granbond::contact::{sphere_plane, sphere_sphere};
use granbond::contact::{ContactOutput, ContactState, Plane, VoigtModel};
use granbond::integrate::{symplectic_euler, Body};
use granbond::kinematics::{KinematicsError, PairKinematics, SphereKinematics};
use granbond::stability::sphere_inertia;
use granbond::vector::{v3, Vec3};
use std::collections::HashMap;

/// A sphere of the scene. A `fixed` sphere moves with its prescribed
/// velocities and ignores the loads on it.
#[derive(Clone, Copy, Debug)]
pub struct Sphere {
    pub body: Body,
    pub radius: f64,
    pub fixed: bool,
    /// Constant external force (N) added every step (a tip load, say).
    pub external_force: Vec3,
}

impl Sphere {
    pub fn new(x: Vec3, radius: f64, density: f64) -> Self {
        let mass = density * 4.0 / 3.0 * std::f64::consts::PI * radius.powi(3);
        Self {
            body: Body {
                x,
                v: Vec3::zeros(),
                w: Vec3::zeros(),
                rotation: Vec3::zeros(),
                mass,
                inertia: sphere_inertia(mass, radius),
            },
            radius,
            fixed: false,
            external_force: Vec3::zeros(),
        }
    }
}

/// A bonded pair and its state.
#[derive(Clone, Copy, Debug)]
pub struct Bond {
    pub i: usize,
    pub j: usize,
    pub state: BondState,
    /// Output of the last step.
    pub last: BondOutput,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SceneError {
    /// A pair's kinematics were unusable (NaN, coincident centres): the
    /// scene has blown up; the step is reported, not hidden.
    Kinematics {
        i: usize,
        j: usize,
        error: KinematicsError,
    },
}

/// What happened in one step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepReport {
    pub bonds_created: usize,
    pub bonds_broken: usize,
    pub broken_by_distance: usize,
    pub broken_by_tension: usize,
    pub broken_by_compression: usize,
    pub broken_by_shear: usize,
    pub contacts: usize,
}

pub struct Scene {
    pub spheres: Vec<Sphere>,
    pub bonds: Vec<Bond>,
    pub bond_model: Option<BondModel>,
    pub contact_model: Option<VoigtModel>,
    pub planes: Vec<Plane>,
    pub gravity: Vec3,
    pub dt: f64,
    pub step: i64,
    bonded: HashMap<(usize, usize), usize>,
    contacts: HashMap<(usize, usize), ContactState>,
    plane_contacts: HashMap<(usize, usize), ContactState>,
    forces: Vec<Vec3>,
    torques: Vec<Vec3>,
}

fn kinematics(a: &Sphere, b: &Sphere) -> PairKinematics {
    PairKinematics {
        x_i: a.body.x.into(),
        x_j: b.body.x.into(),
        v_i: a.body.v.into(),
        v_j: b.body.v.into(),
        w_i: a.body.w.into(),
        w_j: b.body.w.into(),
        radius_i: a.radius,
        radius_j: b.radius,
    }
}

impl Scene {
    pub fn new(dt: f64) -> Self {
        Self {
            spheres: Vec::new(),
            bonds: Vec::new(),
            bond_model: None,
            contact_model: None,
            planes: Vec::new(),
            gravity: Vec3::zeros(),
            dt,
            step: 0,
            bonded: HashMap::new(),
            contacts: HashMap::new(),
            plane_contacts: HashMap::new(),
            forces: Vec::new(),
            torques: Vec::new(),
        }
    }

    pub fn time(&self) -> f64 {
        self.step as f64 * self.dt
    }

    /// Bonds every pair the creation rules allow at the current step.
    pub fn create_bonds(&mut self) -> Result<usize, SceneError> {
        let Some(model) = &self.bond_model else {
            return Ok(0);
        };
        let positions: Vec<Vec3> = self.spheres.iter().map(|s| s.body.x).collect();
        let mut created = 0;
        for (i, j) in close_pairs(&positions, model.params.create_distance) {
            let kin = kinematics(&self.spheres[i], &self.spheres[j]);
            let index = *self.bonded.entry((i, j)).or_insert_with(|| {
                self.bonds.push(Bond {
                    i,
                    j,
                    state: BondState::default(),
                    last: BondOutput::default(),
                });
                self.bonds.len() - 1
            });
            let state = &mut self.bonds[index].state;
            if model
                .try_create(&kin, self.step, state)
                .map_err(|error| SceneError::Kinematics { i, j, error })?
            {
                created += 1;
            }
        }
        self.bonds.retain(|b| b.state.status() != BondStatus::Unbonded);
        self.bonded = self
            .bonds
            .iter()
            .enumerate()
            .map(|(n, b)| ((b.i, b.j), n))
            .collect();
        Ok(created)
    }

    /// Intact bonds.
    pub fn intact_bonds(&self) -> usize {
        self.bonds
            .iter()
            .filter(|b| b.state.status() == BondStatus::Intact)
            .count()
    }

    /// One step: bonds, contacts, planes, then symplectic Euler.
    pub fn advance(&mut self) -> Result<StepReport, SceneError> {
        let mut report = StepReport::default();
        if let Some(model) = &self.bond_model {
            if model.creates_at(self.step) {
                report.bonds_created = self.create_bonds()?;
            }
        }
        let n = self.spheres.len();
        self.forces.clear();
        self.torques.clear();
        self.forces.extend(
            self.spheres
                .iter()
                .map(|s| self.gravity * s.body.mass + s.external_force),
        );
        self.torques.resize(n, Vec3::zeros());

        if let Some(model) = &self.bond_model {
            for bond in &mut self.bonds {
                let (a, b) = (&self.spheres[bond.i], &self.spheres[bond.j]);
                let mut out = BondOutput::default();
                let was_intact = bond.state.status() == BondStatus::Intact;
                model
                    .step(&kinematics(a, b), self.dt, &mut bond.state, &mut out)
                    .map_err(|error| SceneError::Kinematics {
                        i: bond.i,
                        j: bond.j,
                        error,
                    })?;
                bond.last = out;
                if was_intact && out.break_mode != BreakMode::None as i32 {
                    report.bonds_broken += 1;
                    match BreakMode::from_number(f64::from(out.break_mode)) {
                        BreakMode::Distance => report.broken_by_distance += 1,
                        BreakMode::Tension => report.broken_by_tension += 1,
                        BreakMode::Compression => report.broken_by_compression += 1,
                        BreakMode::Shear => report.broken_by_shear += 1,
                        BreakMode::None => {}
                    }
                }
                let f = v3(out.force_i);
                self.forces[bond.i] += f;
                self.forces[bond.j] -= f;
                self.torques[bond.i] += v3(out.torque_i);
                self.torques[bond.j] += v3(out.torque_j);
            }
        }

        if let Some(model) = &self.contact_model {
            let max_radius = self.spheres.iter().map(|s| s.radius).fold(0.0, f64::max);
            let positions: Vec<Vec3> = self.spheres.iter().map(|s| s.body.x).collect();
            let mut touching = HashMap::new();
            for (i, j) in close_pairs(&positions, 2.0 * max_radius) {
                if let Some(&b) = self.bonded.get(&(i, j)) {
                    // An intact bond replaces the contact model (docs/models/bond-nonlinear.md).
                    if self.bonds[b].state.status() == BondStatus::Intact {
                        continue;
                    }
                }
                let (a, b) = (&self.spheres[i], &self.spheres[j]);
                let frame = sphere_sphere(&kinematics(a, b)).map_err(|error| SceneError::Kinematics {
                    i,
                    j,
                    error,
                })?;
                if frame.overlap <= 0.0 {
                    continue;
                }
                let mut state = self.contacts.get(&(i, j)).copied().unwrap_or_default();
                let mut out = ContactOutput::default();
                model.step_frame(&frame, self.dt, &mut state, &mut out);
                touching.insert((i, j), state);
                let f = v3(out.force_i);
                self.forces[i] += f;
                self.forces[j] -= f;
                self.torques[i] += v3(out.torque_i);
                self.torques[j] += v3(out.torque_j);
            }
            report.contacts = touching.len();
            self.contacts = touching;

            let mut touching_planes = HashMap::new();
            for (p, plane) in self.planes.iter().enumerate() {
                for (i, s) in self.spheres.iter().enumerate() {
                    let sphere = SphereKinematics {
                        x: s.body.x.into(),
                        v: s.body.v.into(),
                        w: s.body.w.into(),
                        radius: s.radius,
                    };
                    let frame = sphere_plane(&sphere, plane);
                    if frame.overlap <= 0.0 {
                        continue;
                    }
                    let mut state = self.plane_contacts.get(&(i, p)).copied().unwrap_or_default();
                    let mut out = ContactOutput::default();
                    model.step_frame(&frame, self.dt, &mut state, &mut out);
                    touching_planes.insert((i, p), state);
                    self.forces[i] += v3(out.force_i);
                    self.torques[i] += v3(out.torque_i);
                }
            }
            self.plane_contacts = touching_planes;
        }

        for (s, (f, t)) in self.spheres.iter_mut().zip(self.forces.iter().zip(&self.torques)) {
            if s.fixed {
                s.body.x += s.body.v * self.dt;
                s.body.rotation += s.body.w * self.dt;
            } else {
                symplectic_euler(&mut s.body, *f, *t, self.dt);
            }
        }
        self.step += 1;
        Ok(report)
    }

    /// Load on sphere `i` in the last step.
    pub fn load(&self, i: usize) -> (Vec3, Vec3) {
        (self.forces[i], self.torques[i])
    }

    pub fn kinetic_energy(&self) -> f64 {
        self.spheres
            .iter()
            .map(|s| {
                0.5 * s.body.mass * s.body.v.norm_squared() + 0.5 * s.body.inertia * s.body.w.norm_squared()
            })
            .sum()
    }

    /// Elastic energy of the intact bonds (loading curves, see
    /// `bond::energy`) at the positions of the last step, which is where
    /// their stored shear force and angles stand.
    pub fn bond_energy(&self) -> f64 {
        let Some(model) = &self.bond_model else {
            return 0.0;
        };
        self.bonds
            .iter()
            .map(|b| {
                let (ri, rj) = (self.spheres[b.i].radius, self.spheres[b.j].radius);
                model.elastic_energy(&b.state, b.last.delta, ri, rj).total()
            })
            .sum()
    }

    pub fn linear_momentum(&self) -> Vec3 {
        self.spheres.iter().map(|s| s.body.v * s.body.mass).sum()
    }

    /// About the origin: orbital plus spin.
    pub fn angular_momentum(&self) -> Vec3 {
        self.spheres
            .iter()
            .map(|s| s.body.x.cross(&(s.body.v * s.body.mass)) + s.body.w * s.body.inertia)
            .sum()
    }
}

impl Scene {
    /// Sizes of the groups of spheres held together by intact bonds,
    /// largest first (isolated spheres are fragments of size 1).
    pub fn fragment_sizes(&self) -> Vec<usize> {
        let n = self.spheres.len();
        let mut parent: Vec<usize> = (0..n).collect();
        fn root(parent: &mut [usize], mut i: usize) -> usize {
            while parent[i] != i {
                parent[i] = parent[parent[i]];
                i = parent[i];
            }
            i
        }
        for b in self
            .bonds
            .iter()
            .filter(|b| b.state.status() == BondStatus::Intact)
        {
            let (ri, rj) = (root(&mut parent, b.i), root(&mut parent, b.j));
            parent[ri] = rj;
        }
        let mut sizes: HashMap<usize, usize> = HashMap::new();
        for i in 0..n {
            *sizes.entry(root(&mut parent, i)).or_default() += 1;
        }
        let mut v: Vec<usize> = sizes.into_values().collect();
        v.sort_unstable_by(|a, b| b.cmp(a));
        v
    }
}
