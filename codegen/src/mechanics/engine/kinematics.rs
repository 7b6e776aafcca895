//! The kinematics of a description: the sines and cosines of its angles, each frame's
//! orientation, angular velocity and angular acceleration, each point's position, velocity and
//! acceleration along its rigid chain, and each wheel's contact, all in the working frame's
//! components and at constant speeds (the accelerations' parts that the speeds' derivatives
//! do not give).
//!
//! For points $X = Y + \rho$ with ρ fixed in a frame of angular velocity ω and angular
//! acceleration α: $v_X = v_Y + \omega\times\rho$,
//! $a_X = a_Y + \alpha\times\rho + \omega\times(\omega\times\rho)$. A frame turned from its
//! parent by successive simple rotations $q_k$ about axes $e_k$ has
//! $\omega = \omega_{parent} + \sum_k \dot q_k e_k$ and, at constant rates,
//! $\alpha = \alpha_{parent} + \sum_k \dot q_k\,\omega_{k}\times e_k$, $\omega_k$ the angular
//! velocity of the frame before rotation k (where $e_k$ is fixed).

use std::collections::BTreeMap;

use symbolica::atom::{Atom, AtomCore};

use super::store::{add, cross, mtv, mv, scale, Store, M3, V3};
use super::{Angle, Axis, DescriptionError, Model};
use crate::cas::var;

/// One simple rotation with its sine, cosine and rate.
#[derive(Clone, Debug)]
struct Step {
    axis: Axis,
    s: Atom,
    c: Atom,
    /// The rate (a speed symbol) for a coordinate's rotation; `None` for a constant angle.
    rate: Option<Atom>,
}

impl Step {
    /// The matrix taking components after the rotation to components before it.
    fn matrix(&self) -> M3 {
        let (s, c) = (&self.s, &self.c);
        let (o, z) = (Atom::num(1), Atom::num(0));
        match self.axis {
            Axis::X => {
                [[o, z.clone(), z.clone()], [z.clone(), c.clone(), -s], [z, s.clone(), c.clone()]]
            }
            Axis::Y => {
                [[c.clone(), z.clone(), s.clone()], [z.clone(), o, z.clone()], [-s, z, c.clone()]]
            }
            Axis::Z => {
                [[c.clone(), -s, z.clone()], [s.clone(), c.clone(), z.clone()], [z.clone(), z, o]]
            }
        }
    }
}

/// A frame's motion, in working-frame components.
#[derive(Clone, Debug)]
pub struct FrameMotion {
    /// Angular velocity (linear in the speeds).
    pub omega: V3,
    /// Angular acceleration at constant speeds.
    pub alpha: V3,
}

/// A point's motion relative to the root, in working-frame components.
#[derive(Clone, Debug)]
pub struct PointMotion {
    /// Position relative to the root point.
    pub position: V3,
    /// Velocity (linear in the speeds).
    pub velocity: V3,
    /// Acceleration at constant speeds.
    pub acceleration: V3,
}

/// The kinematics of a whole description.
pub struct Kinematics {
    /// Each frame's parent and rotations (the working frame and the ground have none).
    steps: BTreeMap<String, (String, Vec<Step>)>,
    /// The working frame's name.
    pub working: String,
    /// Each frame's motion (the ground `N` and the working frame included).
    pub frames: BTreeMap<String, FrameMotion>,
    /// The product of each frame's rotations, its entries named where they are not trivial.
    rotations: BTreeMap<String, M3>,
    /// Each frame's motion in its own components (the derivatives of its angular velocity's
    /// components are those of its angular acceleration: $\omega\times\omega = 0$), unnamed.
    pub local: BTreeMap<String, FrameMotion>,
    /// Each point's motion (the root included).
    pub points: BTreeMap<String, PointMotion>,
}

/// The names of the sine and cosine of an angle: `s_<name>`, `c_<name>`.
fn trig_names(name: &str) -> (String, String) {
    (format!("s_{name}"), format!("c_{name}"))
}

impl Kinematics {
    /// The kinematics of `m`, its named quantities recorded in `st`.
    pub fn new(m: &Model, st: &mut Store) -> Result<Kinematics, DescriptionError> {
        let working = match &m.heading {
            Some(h) => {
                let f = m.frames.first().filter(|f| {
                    f.parent == "N"
                        && f.rotations.len() == 1
                        && f.rotations[0].axis == Axis::Z
                        && matches!(&f.rotations[0].angle, Angle::Coordinate(c) if c == h)
                });
                f.ok_or_else(|| DescriptionError::Constraints {
                    reason: format!(
                        "the first frame must be the ground turned about its vertical by the heading {h}"
                    ),
                })?
                .name
                .clone()
            }
            None => "N".to_string(),
        };
        let mut k = Kinematics {
            steps: BTreeMap::new(),
            working: working.clone(),
            frames: BTreeMap::new(),
            local: BTreeMap::new(),
            rotations: BTreeMap::new(),
            points: BTreeMap::new(),
        };
        let zero = [Atom::num(0), Atom::num(0), Atom::num(0)];
        let heading_rate = match &m.heading {
            Some(h) => var(&format!("{h}d")),
            None => Atom::num(0),
        };
        let w_motion =
            FrameMotion { omega: [Atom::num(0), Atom::num(0), heading_rate], alpha: zero.clone() };
        k.frames.insert("N".into(), FrameMotion { omega: zero.clone(), alpha: zero.clone() });
        k.local.insert("N".into(), FrameMotion { omega: zero.clone(), alpha: zero.clone() });
        k.local.insert(working.clone(), w_motion.clone());
        k.frames.insert(working.clone(), w_motion);
        // Sines and cosines, named once per angle.
        let mut trig: BTreeMap<String, (Atom, Atom)> = BTreeMap::new();
        for f in &m.frames {
            if f.name == working {
                continue;
            }
            if f.parent == "N" && working != "N" {
                return Err(DescriptionError::Constraints {
                    reason: format!(
                        "frame {} hangs from the ground: with a heading every frame hangs from the working frame {working}",
                        f.name
                    ),
                });
            }
            let mut steps = Vec::new();
            for r in &f.rotations {
                let (key, rate, sign) = match &r.angle {
                    Angle::Coordinate(c) => (c.clone(), Some(var(&format!("{c}d"))), 1),
                    Angle::Parameter { name, negated } => {
                        (name.clone(), None, if *negated { -1 } else { 1 })
                    }
                };
                if !trig.contains_key(&key) {
                    let (sn, cn) = trig_names(&key);
                    let s = st.put(&sn, &format!("sin({key})"), var(&format!("sin({key})")));
                    let c = st.put(&cn, &format!("cos({key})"), var(&format!("cos({key})")));
                    if let Some(rate) = &rate {
                        st.set_rate(&st.full(&sn), &c * rate);
                        st.set_rate(&st.full(&cn), -(&s * rate));
                    }
                    trig.insert(key.clone(), (s, c));
                }
                let (s, c) = trig[&key].clone();
                steps.push(Step { axis: r.axis, s: Atom::num(sign) * s, c, rate });
            }
            k.steps.insert(f.name.clone(), (f.parent.clone(), steps));
        }
        // Frame motions, parents first.
        for f in &m.frames {
            if f.name == working {
                continue;
            }
            let (parent, steps) = k.steps[&f.name].clone();
            let pm = k.frames[&parent].clone();
            let (mut omega, mut alpha) = (pm.omega.clone(), pm.alpha.clone());
            for (i, step) in steps.iter().enumerate() {
                if let Some(rate) = &step.rate {
                    let e =
                        k.up_from(st, &step.axis.unit(), &f.name, i, &format!("e_{}_{i}", f.name));
                    alpha = add(&alpha, &scale(rate, &cross(&omega, &e)));
                    omega = add(&omega, &scale(rate, &e));
                }
            }
            let omega = super::store::expand3(&omega);
            let alpha = super::store::expand3(&alpha);
            k.frames.insert(f.name.clone(), FrameMotion { omega, alpha });
            // In the frame's own components. The product R of the frame's rotations (parent components = R frame components)
            // is named entry by entry when there are several (a steer rotation
            // R_y(l) R_z(d) R_y(-l) multiplied out into every vector costs hundreds of
            // operations), and each rotation's terms are written in the frame's components: its
            // axis e_k as L_k^T e_k, L_k the product of the rotations after it (rotations keep
            // cross products); a rotation adds rate e to the angular velocity and
            // rate (omega_before x e) to the acceleration.
            let lm = k.local[&parent].clone();
            let r = k.rotation(st, &f.name);
            let mut omega = mtv(&r, &lm.omega);
            let mut alpha = mtv(&r, &lm.alpha);
            for (i, step) in steps.iter().enumerate() {
                if let Some(rate) = &step.rate {
                    let mut e = step.axis.unit();
                    for later in &steps[i + 1..] {
                        e = mtv(&later.matrix(), &e);
                    }
                    alpha = add(&alpha, &scale(rate, &cross(&omega, &e)));
                    omega = add(&omega, &scale(rate, &e));
                }
            }
            k.local.insert(f.name.clone(), FrameMotion { omega, alpha });
        }
        // The root: on the ground, moving with the speeds (root_u, root_v) along W's axes.
        let v_root = [var(&format!("{}_u", m.root)), var(&format!("{}_v", m.root)), Atom::num(0)];
        let a_root = cross(&k.frames[&working].omega, &v_root);
        k.points.insert(
            m.root.clone(),
            PointMotion { position: zero.clone(), velocity: v_root, acceleration: a_root },
        );
        for p in &m.points {
            let rho = k.up(st, &p.offset, &p.frame, &format!("r_{}", p.name));
            let from = k.points[&p.from].clone();
            let fm = k.frames[&p.frame].clone();
            k.points.insert(p.name.clone(), k.rigid(&from, &fm, &rho));
        }
        Ok(k)
    }

    /// The product of `frame`'s rotations (parent components = R frame components), its
    /// entries named `R_<frame>_<row><column>` (numbers, symbols and their multiples unnamed).
    fn rotation(&mut self, st: &mut Store, frame: &str) -> M3 {
        if let Some(r) = self.rotations.get(frame) {
            return r.clone();
        }
        let steps = &self.steps[frame].1;
        let (o, z) = (Atom::num(1), Atom::num(0));
        let mut r: M3 = [
            [o.clone(), z.clone(), z.clone()],
            [z.clone(), o.clone(), z.clone()],
            [z.clone(), z, o],
        ];
        for step in steps {
            let m = step.matrix();
            r = [0, 1, 2].map(|i| {
                [0, 1, 2].map(|j| {
                    (&r[i][0] * &m[0][j] + &r[i][1] * &m[1][j] + &r[i][2] * &m[2][j]).expand()
                })
            });
        }
        let named: M3 = [0, 1, 2].map(|i| {
            [0, 1, 2].map(|j| {
                st.name(
                    &format!("R_{frame}_{}{}", i + 1, j + 1),
                    &format!("entry ({}, {}) of the product of {frame}'s rotations", i + 1, j + 1),
                    r[i][j].clone(),
                )
            })
        });
        self.rotations.insert(frame.to_string(), named.clone());
        named
    }

    /// The motion of the point `from + rho`, `rho` fixed in a frame of motion `fm`.
    pub fn rigid(&self, from: &PointMotion, fm: &FrameMotion, rho: &V3) -> PointMotion {
        let wr = cross(&fm.omega, rho);
        PointMotion {
            position: super::store::expand3(&add(&from.position, rho)),
            velocity: add(&from.velocity, &wr),
            acceleration: add(
                &add(&from.acceleration, &cross(&fm.alpha, rho)),
                &cross(&fm.omega, &wr),
            ),
        }
    }

    /// Components in the working frame of a vector given in `frame`'s components, each level of
    /// the chain of rotations named `<name>_<level>`.
    pub fn up(&self, st: &mut Store, v: &V3, frame: &str, name: &str) -> V3 {
        let n = self.steps.get(frame).map_or(0, |s| s.1.len());
        self.up_from(st, v, frame, n, name)
    }

    /// As [`Kinematics::up`], for a vector given in the components of `frame` after its first
    /// `k` rotations.
    pub fn up_from(&self, st: &mut Store, v: &V3, frame: &str, k: usize, name: &str) -> V3 {
        let mut v = v.clone();
        let mut frame = frame.to_string();
        let mut k = k;
        let mut level = 0;
        while let Some((parent, steps)) = self.steps.get(&frame) {
            match self.rotations.get(&frame) {
                Some(r) if k == steps.len() => v = mv(r, &v),
                _ => {
                    for step in steps[..k].iter().rev() {
                        v = mv(&step.matrix(), &v);
                    }
                }
            }
            level += 1;
            v = st.name3(&format!("{name}_{level}"), &format!("{name} at level {level}"), &v);
            frame = parent.clone();
            k = self.steps.get(&frame).map_or(0, |s| s.1.len());
        }
        v
    }

    /// Components in `frame` of a vector given in the working frame's components, each level
    /// named `<name>_<level>`.
    pub fn down(&self, st: &mut Store, v: &V3, frame: &str, name: &str) -> V3 {
        let mut chain = Vec::new();
        let mut f = frame.to_string();
        while let Some((parent, _)) = self.steps.get(&f) {
            chain.push(f.clone());
            f = parent.clone();
        }
        let mut v = v.clone();
        for (level, f) in chain.iter().rev().enumerate() {
            for step in &self.steps[f].1 {
                v = mtv(&step.matrix(), &v);
            }
            v = st.name3(&format!("{name}_{}", level + 1), &format!("{name} in {f}"), &v);
        }
        v
    }
}
