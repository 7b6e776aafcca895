//! Kane's method on a description: the wheels' rolling constraints, the dependent speeds and the
//! velocity parts of their accelerations solved row by row (triangular order, no symbolic
//! inversion), the non-holonomic partial velocities and the generalised inertia and active forces
//! $$M_{ij} = \sum_X m_X\,\tilde v_{X,i}\cdot\tilde v_{X,j} + \tilde\omega_{X,i}\cdot I_X\tilde\omega_{X,j},\qquad
//! f_i = \sum_X m_X (g\hat z - a^0_X)\cdot\tilde v_{X,i}
//! - (I_X\alpha^0_X + \omega_X\times I_X\omega_X)\cdot\tilde\omega_{X,i} + \sum_T T\,e_T\cdot\tilde\omega_{T,i}.$$
//!
//! Each wheel gives three rows: the velocity of its material contact point along the vertical,
//! along the horizontal projection $(a_x, a_y, 0)$ of its axle and along $(a_y, -a_x, 0)$. A
//! row that vanishes identically (the vertical row of a wheel whose contact is the root point)
//! is dropped; a row implied by the others (two wheels on one axle) is detected numerically at a
//! seeded point, named in the result and dropped; a row that still constrains the independent
//! speeds once every dependent speed is solved is an error naming it.

use std::collections::BTreeMap;

use symbolica::atom::{Atom, AtomCore};

use super::kinematics::{FrameMotion, Kinematics, PointMotion};
use super::store::{add, cross, d, dot, expand3, mv, scale, sub, zero3, Store, M3, V3};
use super::{DescriptionError, Model};
use crate::cas::var;

/// One body of Kane's sums (a rigid body or a wheel) with its kinematics.
#[derive(Clone, Debug)]
pub struct MassBody {
    /// Its name.
    pub name: String,
    /// Its mass.
    pub mass: Atom,
    /// Its inertia about its mass centre, in `frame`'s axes.
    pub inertia: M3,
    /// The frame whose axes `inertia` is written in.
    pub frame: String,
    /// Its mass centre's motion.
    pub centre: PointMotion,
    /// Its angular velocity and acceleration (working-frame components).
    pub motion: FrameMotion,
}

/// A row of the velocity constraints.
#[derive(Clone, Debug)]
pub struct Row {
    /// Which wheel and direction (`R vertical`, `F lateral`, ...).
    pub label: String,
    /// Its coefficient of each speed (named), by speed name; zero coefficients omitted.
    pub coef: BTreeMap<String, Atom>,
    /// The row's time derivative at constant speeds: the time derivative of the expression
    /// `dir . v_contact`, not `dir . a` of the wheel's material point at the contact (that
    /// point moves round the rim, so its acceleration is not the derivative of the row).
    pub rate: Atom,
    /// The direction of the row.
    pub dir: V3,
}

/// What Kane's method produces, beyond the formulas it records in the store.
pub struct Kane {
    /// The kinematics.
    pub kin: Kinematics,
    /// The bodies of the sums.
    pub bodies: Vec<MassBody>,
    /// The independent speeds.
    pub independent: Vec<String>,
    /// The dependent speeds, in the order they were solved.
    pub dependent: Vec<String>,
    /// `a[d][i]`: the coefficient of independent speed i in dependent speed d (named).
    pub a: BTreeMap<String, Vec<Atom>>,
    /// The velocity part of each dependent speed's derivative (named).
    pub w: BTreeMap<String, Atom>,
    /// The rows found redundant and dropped, with the reason.
    pub redundant: Vec<String>,
    /// The rows that vanish identically.
    pub vanishing: Vec<String>,
    /// The mass matrix (symbols of the store).
    pub m: Vec<Vec<Atom>>,
    /// The forcing (symbols of the store).
    pub f: Vec<Atom>,
    /// The contact heights (holonomic constraints) by wheel, named.
    pub heights: Vec<(String, Atom)>,
    /// The potential energy (named).
    pub potential: Atom,
    /// Per body: the partial velocities of its mass centre (working-frame components) and its
    /// partial angular velocities (in its frame's components), by independent speed.
    pub partials: Vec<(Vec<V3>, Vec<V3>)>,
    /// The generalised active forces of the torques, by independent speed (unnamed).
    pub torque_forces: Vec<Atom>,
}

/// A seeded point at which to judge coefficients numerically: every parameter and coordinate a
/// value in (0.2, 1.2) from a fixed linear congruential sequence, so that no symmetry makes a
/// coefficient vanish by accident.
pub fn seeded_point(m: &Model) -> BTreeMap<String, f64> {
    let mut state: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        0.2 + ((state >> 11) as f64 / (1u64 << 53) as f64)
    };
    let mut p = BTreeMap::new();
    for name in m.params.iter().chain(&m.inputs) {
        p.insert(name.clone(), next());
    }
    for c in &m.coordinates {
        p.insert(c.name.clone(), next());
    }
    p
}

fn wheel_inertia(axis: usize, diametral: &Atom, axial: &Atom) -> M3 {
    let mut i: M3 = [zero3(), zero3(), zero3()];
    for (k, row) in i.iter_mut().enumerate() {
        row[k] = if k == axis { axial.clone() } else { diametral.clone() };
    }
    i
}

/// Derives Kane's equations of `m`, recording every quantity in `st`.
pub fn derive(m: &Model, st: &mut Store) -> Result<Kane, DescriptionError> {
    m.validate()?;
    let kin = Kinematics::new(m, st)?;
    let independent = m.independent_speeds();
    let dependent_all = m.dependent_speeds();
    let speeds: Vec<String> = independent.iter().chain(&dependent_all).cloned().collect();
    let zhat: V3 = [Atom::num(0), Atom::num(0), Atom::num(1)];

    // Bodies and wheels with their kinematics; the wheels' contacts and rows.
    let mut bodies = Vec::new();
    for b in &m.bodies {
        bodies.push(MassBody {
            name: b.name.clone(),
            mass: b.mass.clone(),
            inertia: b.inertia.clone(),
            frame: b.frame.clone(),
            centre: kin.points[&b.centre].clone(),
            motion: kin.frames[&b.frame].clone(),
        });
    }
    let mut rows = Vec::new();
    let mut heights = Vec::new();
    for wh in &m.wheels {
        let carrier = kin.frames[&wh.carrier].clone();
        let a = kin.up(st, &wh.axle.unit(), &wh.carrier, &format!("a_{}", wh.name));
        let spin = var(&format!("{}d", wh.spin));
        let motion = FrameMotion {
            omega: expand3(&add(&carrier.omega, &scale(&spin, &a))),
            alpha: expand3(&add(&carrier.alpha, &scale(&spin, &cross(&carrier.omega, &a)))),
        };
        let down = match &wh.down {
            Some((f, axis)) => kin.up(st, &axis.unit(), f, &format!("d_{}", wh.name)),
            None => {
                let n = st.name(
                    &format!("n_{}", wh.name),
                    &format!(
                        "sqrt(1 - a_z^2) for wheel {}: the vertical's projection on its plane",
                        wh.name
                    ),
                    (Atom::num(1) - a[2].pow(Atom::num(2))).pow(Atom::num(1) / Atom::num(2)),
                );
                [-(&a[2] * &a[0]) / &n, -(&a[2] * &a[1]) / &n, n.clone()]
            }
        };
        let centre = kin.points[&wh.centre].clone();
        let rd = scale(&wh.radius, &down);
        let contact = kin.rigid(&centre, &motion, &rd);
        if !wh.at_root {
            let h = st.name(
                &format!("{}_contact_height", wh.name),
                &format!(
                    "height (down positive) of wheel {}'s lowest point: the holonomic constraint",
                    wh.name
                ),
                contact.position[2].clone(),
            );
            heights.push((wh.name.clone(), h));
        }
        let dirs: [(&str, V3); 3] = [
            ("vertical", zhat.clone()),
            ("lateral", [a[0].clone(), a[1].clone(), Atom::num(0)]),
            ("longitudinal", [a[1].clone(), -&a[0], Atom::num(0)]),
        ];
        for (label, dir) in dirs {
            let row = dot(&dir, &contact.velocity).expand();
            let mut coef = BTreeMap::new();
            for s in &speeds {
                let c = d(&row, s).expand();
                if !c.is_zero() {
                    coef.insert(s.clone(), c);
                }
            }
            // Taken now, before the dependent speeds get formulas: at constant speeds.
            let rate = st.dt(&row);
            rows.push(Row { label: format!("{} {label}", wh.name), coef, rate, dir });
        }
        bodies.push(MassBody {
            name: wh.name.clone(),
            mass: wh.mass.clone(),
            inertia: wheel_inertia(wh.axle.index(), &wh.diametral, &wh.axial),
            frame: wh.carrier.clone(),
            centre,
            motion,
        });
    }

    // Solve the rows for the dependent speeds in triangular order.
    let mut point = seeded_point(m);
    for s in &speeds {
        point.insert(s.clone(), 0.0);
    }
    let mut vanishing = Vec::new();
    let mut live: Vec<Row> = Vec::new();
    for r in rows {
        if r.coef.is_empty() {
            vanishing.push(r.label.clone());
        } else {
            live.push(r);
        }
    }
    // Name the coefficients.
    for (k, r) in live.iter_mut().enumerate() {
        let label = r.label.replace(' ', "_");
        for (s, c) in r.coef.iter_mut() {
            *c = st.name(
                &format!("b_{label}_{s}"),
                &format!("coefficient of {s} in row {}", r.label),
                c.clone(),
            );
        }
        let _ = k;
    }
    let mut a: BTreeMap<String, Vec<Atom>> = BTreeMap::new();
    let mut order: Vec<(String, usize)> = Vec::new();
    let mut used = vec![false; live.len()];
    let numeric = |st: &Store, e: &Atom, point: &mut BTreeMap<String, f64>| {
        st.eval(e, point).unwrap_or(f64::NAN)
    };
    loop {
        let unsolved: Vec<&String> = dependent_all.iter().filter(|d| !a.contains_key(*d)).collect();
        if unsolved.is_empty() {
            break;
        }
        let mut pick = None;
        for (k, r) in live.iter().enumerate() {
            if used[k] {
                continue;
            }
            let open: Vec<&String> = unsolved
                .iter()
                .copied()
                .filter(|d| r.coef.get(*d).is_some_and(|c| numeric(st, c, &mut point).abs() > 1e-9))
                .collect();
            if open.len() == 1 {
                pick = Some((k, open[0].clone()));
                break;
            }
        }
        let Some((k, dep)) = pick else {
            return Err(DescriptionError::Constraints {
                reason: format!(
                    "no remaining row gives one of the dependent speeds {unsolved:?} alone (the rows are not triangular, or a dependent speed is not constrained)"
                ),
            });
        };
        used[k] = true;
        let r = &live[k];
        let cd = r.coef[&dep].clone();
        let mut coefs = Vec::new();
        for (i, ind) in independent.iter().enumerate() {
            let mut e = r.coef.get(ind).cloned().unwrap_or_else(|| Atom::num(0));
            for (s, cs) in &r.coef {
                if let Some(av) = a.get(s) {
                    e += cs * &av[i];
                }
            }
            let e = -(e / &cd);
            coefs.push(st.name(
                &format!("A_{dep}_{ind}"),
                &format!("d {dep} / d {ind}: from row {}", r.label),
                e,
            ));
        }
        a.insert(dep.clone(), coefs);
        order.push((dep, k));
    }
    // The remaining rows must be implied by the others (numerically at the seeded point).
    let mut redundant = Vec::new();
    for (k, r) in live.iter().enumerate() {
        if used[k] {
            continue;
        }
        let mut worst: f64 = 0.0;
        for (i, ind) in independent.iter().enumerate() {
            let mut e = r.coef.get(ind).cloned().unwrap_or_else(|| Atom::num(0));
            for (s, cs) in &r.coef {
                if let Some(av) = a.get(s) {
                    e += cs * &av[i];
                }
            }
            worst = worst.max(numeric(st, &e, &mut point).abs());
        }
        if worst > 1e-9 {
            return Err(DescriptionError::Constraints {
                reason: format!(
                    "row {} constrains the independent speeds once the dependent speeds are solved (residual coefficient {worst:e}): declare one more dependent speed or remove the constraint",
                    r.label
                ),
            });
        }
        redundant.push(format!("{}: implied by the other rows (residual {worst:.1e})", r.label));
    }
    // The dependent speeds as formulas (their names are the speeds' own, so later formulas that
    // contain them use their values).
    let dependent: Vec<String> = order.iter().map(|(d, _)| d.clone()).collect();
    for (dep, _) in &order {
        let mut e = Atom::num(0);
        for (i, ind) in independent.iter().enumerate() {
            e += &a[dep][i] * var(ind);
        }
        let _ = st.put_exact(
            dep,
            &format!("{dep}, a dependent speed, from the rolling constraints"),
            e,
        );
    }
    // Velocity parts of the dependent accelerations: d(row)/dt at constant speeds
    // + sum c_s w_s = -c_d w_d.
    let mut w: BTreeMap<String, Atom> = BTreeMap::new();
    for (dep, k) in &order {
        let r = &live[*k];
        let label = r.label.replace(' ', "_");
        let acc = st.name(
            &format!("rowacc_{label}"),
            &format!("time derivative at constant speeds of row {}", r.label),
            r.rate.clone(),
        );
        let mut e = acc;
        for (s, cs) in &r.coef {
            if let Some(ws) = w.get(s) {
                e += cs * ws;
            }
        }
        let wd = st.name(
            &format!("w_{dep}"),
            &format!("velocity part of d {dep}/dt (at zero independent accelerations)"),
            -(e / &r.coef[dep]),
        );
        w.insert(dep.clone(), wd);
    }

    // Kane's sums.
    let n = independent.len();
    let mut mm = vec![vec![Atom::num(0); n]; n];
    let mut f = vec![Atom::num(0); n];
    let g = m.gravity.clone();
    let partial = |v: &V3, i: usize| -> V3 {
        let mut out = [0, 1, 2].map(|c| d(&v[c], &independent[i]));
        for dep in &dependent {
            let dv = [0, 1, 2].map(|c| d(&v[c], dep));
            out = add(&out, &scale(&a[dep][i], &dv));
        }
        expand3(&out)
    };
    let velocity_part = |v: &V3| -> V3 {
        let mut out = zero3();
        for dep in &dependent {
            let dv = [0, 1, 2].map(|c| d(&v[c], dep));
            out = add(&out, &scale(&w[dep], &dv));
        }
        out
    };
    let mut potential = Atom::num(0);
    let mut partials = Vec::new();
    for b in &bodies {
        let x = &b.name;
        let vt: Vec<V3> = (0..n)
            .map(|i| {
                st.name3(
                    &format!("vt_{x}_{}", independent[i]),
                    &format!("partial velocity of {x}'s mass centre for {}", independent[i]),
                    &partial(&b.centre.velocity, i),
                )
            })
            .collect();
        let wt_w: Vec<V3> = (0..n).map(|i| partial(&b.motion.omega, i)).collect();
        let wt: Vec<V3> = (0..n)
            .map(|i| kin.down(st, &wt_w[i], &b.frame, &format!("wt_{x}_{}", independent[i])))
            .collect();
        let a0 = st.name3(
            &format!("a0_{x}"),
            &format!("acceleration of {x}'s mass centre at zero independent accelerations"),
            &expand3(&add(&b.centre.acceleration, &velocity_part(&b.centre.velocity))),
        );
        let alpha0_w = expand3(&add(&b.motion.alpha, &velocity_part(&b.motion.omega)));
        let alpha0 = kin.down(st, &alpha0_w, &b.frame, &format!("al0_{x}"));
        let omega = kin.down(st, &b.motion.omega, &b.frame, &format!("om_{x}"));
        let iw = mv(&b.inertia, &omega);
        let torque = add(&mv(&b.inertia, &alpha0), &cross(&omega, &iw));
        let force =
            sub(&scale(&g, &[Atom::num(0), Atom::num(0), b.mass.clone()]), &scale(&b.mass, &a0));
        for i in 0..n {
            for j in i..n {
                mm[i][j] = &mm[i][j]
                    + &b.mass * dot(&vt[i], &vt[j])
                    + dot(&wt[i], &mv(&b.inertia, &wt[j]));
            }
            f[i] = &f[i] + dot(&force, &vt[i]) - dot(&torque, &wt[i]);
        }
        potential -= &b.mass * &g * &b.centre.position[2];
        partials.push((vt, wt));
    }
    let mut torque_forces = vec![Atom::num(0); n];
    // A torque acts between frames or wheels; a wheel's axes are its carrier's.
    let turning = |name: &str| -> (V3, String) {
        match m.wheels.iter().find(|w| w.name == name) {
            Some(w) => {
                let b = bodies.iter().find(|b| b.name == w.name).expect("every wheel is a body");
                (b.motion.omega.clone(), w.carrier.clone())
            }
            None => (kin.frames[name].omega.clone(), name.to_string()),
        }
    };
    for t in &m.torques {
        let (to_omega, axes) = turning(&t.to);
        let (from_omega, _) = turning(&t.from);
        let e = kin.up(st, &t.axis.unit(), &axes, &format!("e_{}", t.name));
        for i in 0..n {
            let to = partial(&to_omega, i);
            let from = partial(&from_omega, i);
            let q = &t.value * dot(&e, &sub(&to, &from));
            f[i] = &f[i] + &q;
            torque_forces[i] = &torque_forces[i] + q;
        }
    }
    let mut msym = vec![vec![Atom::num(0); n]; n];
    for i in 0..n {
        for j in i..n {
            let s = st.put(
                &format!("M_{}_{}", independent[i], independent[j]),
                &format!("mass matrix entry for ({}, {})", independent[i], independent[j]),
                mm[i][j].expand(),
            );
            msym[i][j] = s.clone();
            msym[j][i] = s;
        }
    }
    let fsym: Vec<Atom> = (0..n)
        .map(|i| {
            st.put(
                &format!("f_{}", independent[i]),
                &format!("forcing of the {} equation: M u' = f", independent[i]),
                f[i].expand(),
            )
        })
        .collect();
    let potential =
        st.name("potential", "gravity's potential energy, zero at ground level (J)", potential);
    Ok(Kane {
        kin,
        bodies,
        independent,
        dependent,
        a,
        w,
        redundant,
        vanishing,
        m: msym,
        f: fsym,
        heights,
        potential,
        partials,
        torque_forces,
    })
}
