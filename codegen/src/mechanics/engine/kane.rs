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

/// A wheel's spin inside an assembly.
struct Spin {
    /// The spin's speed (`<coordinate>d`).
    speed: String,
    /// The axle, an axis of the assembly's frame.
    axis: super::Axis,
    /// The moment of inertia about the axle.
    axial: Atom,
}

/// One term of Kane's sums: a body with the wheels it carries, or a wheel alone.
struct Assembly {
    /// Its name (`T_<body or wheel>`).
    name: String,
    /// The frame its parts are fixed in (the body's, the wheels' carrier).
    frame: String,
    /// The point the parts' offsets start from.
    from: String,
    /// Each part's mass, inertia about its own mass centre and offset from `from`, in `frame`'s
    /// axes.
    parts: Vec<(Atom, M3, V3)>,
    /// The wheels' spins.
    spins: Vec<Spin>,
}

/// The offset from point `x` to point `p` when the chain from `x` to `p` is made of offsets
/// fixed in `frame` (their sum, in its axes); `None` otherwise.
fn offset_from(m: &Model, x: &str, p: &str, frame: &str) -> Option<V3> {
    let mut sum = zero3();
    let mut at = p.to_string();
    while at != x {
        let q = m.points.iter().find(|q| q.name == at)?;
        if q.frame != frame {
            return None;
        }
        sum = add(&sum, &q.offset);
        at = q.from.clone();
    }
    Some(sum)
}

/// The assemblies of Kane's sums: each body with the most wheels its frame carries at offsets
/// fixed in it from one point of the body's chain (the nearest such point), then each wheel
/// left over on its own.
fn assemblies(m: &Model) -> Vec<Assembly> {
    let mut claimed = vec![false; m.wheels.len()];
    let mut out = Vec::new();
    let wheel_part = |wh: &super::Wheel, o: V3| -> (Atom, M3, V3) {
        (wh.mass.clone(), wheel_inertia(wh.axle.index(), &wh.diametral, &wh.axial), o)
    };
    let spin = |wh: &super::Wheel| Spin {
        speed: format!("{}d", wh.spin),
        axis: wh.axle,
        axial: wh.axial.clone(),
    };
    for b in &m.bodies {
        // The body's centre and the points its chain passes through in its own frame.
        let mut best: Option<(String, Vec<usize>)> = None;
        let mut x = b.centre.clone();
        loop {
            if offset_from(m, &x, &b.centre, &b.frame).is_none() {
                break;
            }
            let here: Vec<usize> = (0..m.wheels.len())
                .filter(|&k| {
                    !claimed[k]
                        && m.wheels[k].carrier == b.frame
                        && offset_from(m, &x, &m.wheels[k].centre, &b.frame).is_some()
                })
                .collect();
            if best.as_ref().is_none_or(|(_, w)| here.len() > w.len()) {
                best = Some((x.clone(), here));
            }
            match m.points.iter().find(|q| q.name == x) {
                Some(q) => x = q.from.clone(),
                None => break,
            }
        }
        let (from, wheels) = best.expect("the body's centre is its own reference");
        let mut parts = vec![(
            b.mass.clone(),
            b.inertia.clone(),
            offset_from(m, &from, &b.centre, &b.frame).expect("checked"),
        )];
        let mut spins = Vec::new();
        for &k in &wheels {
            claimed[k] = true;
            let wh = &m.wheels[k];
            parts.push(wheel_part(
                wh,
                offset_from(m, &from, &wh.centre, &b.frame).expect("checked"),
            ));
            spins.push(spin(wh));
        }
        out.push(Assembly {
            name: format!("T_{}", b.name),
            frame: b.frame.clone(),
            from,
            parts,
            spins,
        });
    }
    for (k, wh) in m.wheels.iter().enumerate() {
        if !claimed[k] {
            out.push(Assembly {
                name: format!("T_{}", wh.name),
                frame: wh.carrier.clone(),
                from: wh.centre.clone(),
                parts: vec![wheel_part(wh, zero3())],
                spins: vec![spin(wh)],
            });
        }
    }
    out
}

/// A spin's partial rates (1 for its own independent speed, its constraint coefficients for a
/// dependent one) and its acceleration at zero independent accelerations.
fn spin_rates(
    speed: &str,
    independent: &[String],
    a: &BTreeMap<String, Vec<Atom>>,
    w: &BTreeMap<String, Atom>,
) -> (Vec<Atom>, Atom) {
    match a.get(speed) {
        Some(coefs) => (coefs.clone(), w[speed].clone()),
        None => {
            (independent.iter().map(|u| Atom::num(i64::from(u == speed))).collect(), Atom::num(0))
        }
    }
}

/// A body's angular velocity in its frame's components (a wheel's in its carrier's, with its
/// spin about the axle).
fn body_omega(kin: &Kinematics, m: &Model, b: &MassBody) -> V3 {
    let omega = kin.local[&b.frame].omega.clone();
    match m.wheels.iter().find(|w| w.name == b.name) {
        Some(wh) => expand3(&add(&omega, &scale(&var(&format!("{}d", wh.spin)), &wh.axle.unit()))),
        None => omega,
    }
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
        for (k, c) in ["x", "y", "z"].iter().enumerate() {
            let _ = st.put(
                &format!("axle_{}_{c}", wh.name),
                &format!("wheel {}'s axle, {c} component (working frame)", wh.name),
                a[k].clone(),
            );
        }
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
        // The rows' time derivatives at constant speeds. Row k is e_k . v_c, the material
        // contact point's velocity v_c = v_C + omega x (r d) (working-frame components), so
        // its derivative is e_k' . v_c + e_k . (v_c' - Omega_W x v_c): every term but
        // e_k . (dv_c/dt) carries v_c, which vanishes wherever the dependent speeds satisfy
        // the rows, as their formulas make them do. The inertial derivative is built from
        // named factors, dv_c/dt = a_C + alpha x (r d) + omega x (r d'), with d' = (d's
        // components)' + Omega_W x d, instead of differentiating the expanded rows (which took
        // a quarter of the operations of M and f). Taken now, before the dependent speeds get
        // formulas: at constant speeds.
        let omega_w = kin.frames[&kin.working].omega.clone();
        let d_rate = add(&down.clone().map(|x| st.dt(&x)), &cross(&omega_w, &down));
        let contact_rate = add(
            &add(&centre.acceleration, &cross(&motion.alpha, &rd)),
            &cross(&motion.omega, &scale(&wh.radius, &d_rate)),
        );
        // Expanded when that is shorter: at a wheel whose contact is the root point, terms of
        // omega_L x rho and omega_R x (r d) cancel (rho = -r d) only expanded.
        let contact_rate = contact_rate.map(|c| {
            let e = c.expand();
            if super::store::tree_ops(&e) < super::store::tree_ops(&c) {
                e
            } else {
                c
            }
        });
        let contact_rate = st.name3(
                &format!("vc_{}_dt", wh.name),
                &format!("inertial derivative at constant speeds of wheel {}'s material contact point's velocity", wh.name),
                &contact_rate,
            );
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
            for (k, axis) in ["x", "y"].iter().enumerate() {
                let _ = st.put(
                    &format!("{}_contact_{axis}", wh.name),
                    &format!(
                        "wheel {}'s contact point relative to the root point, along the working frame's {axis} axis (m)",
                        wh.name
                    ),
                    contact.position[k].clone(),
                );
            }
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
            let rate = dot(&dir, &contact_rate);
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
        out
    };
    let velocity_part = |v: &V3| -> V3 {
        let mut out = zero3();
        for dep in &dependent {
            let dv = [0, 1, 2].map(|c| d(&v[c], dep));
            out = add(&out, &scale(&w[dep], &dv));
        }
        out
    };
    // Every body's own partial velocities, for the modified Lagrange equations (Kane's sums
    // below run over assemblies): the mass centre's in working-frame components, the angular
    // ones in the body's frame's components (a wheel's: its carrier's, with its spin).
    // The partials of `v` for each independent speed, named `<name>_<speed>` and described as
    // "<what> for <speed><after>".
    // With `every`, each component is an output, also those too simple to name
    // ([`Store::name3_all`]).
    let named_partials =
        |st: &mut Store, name: &str, what: &str, after: &str, v: &V3, every: bool| -> Vec<V3> {
            (0..n)
                .map(|i| {
                    let name = format!("{name}_{}", independent[i]);
                    let what = format!("{what} for {}{after}", independent[i]);
                    if every {
                        st.name3_all(&name, &what, &partial(v, i))
                    } else {
                        st.name3(&name, &what, &partial(v, i))
                    }
                })
                .collect()
        };
    let mut partials = Vec::new();
    for b in &bodies {
        let x = &b.name;
        let what = format!("partial velocity of {x}'s mass centre");
        // Every component of a body's partial velocities is an output: its velocity and
        // angular velocity for any speeds.
        let vt = named_partials(st, &format!("vt_{x}"), &what, "", &b.centre.velocity, true);
        // Its acceleration at zero independent accelerations: with the partial velocities, the
        // mass centre's acceleration for any independent accelerations (a wheel centre's is
        // what Basu-Mandal et al. tabulate).
        let _ = st.name3_all(
            &format!("a0_{x}"),
            &format!("acceleration of {x}'s mass centre at zero independent accelerations"),
            &add(&b.centre.acceleration, &velocity_part(&b.centre.velocity)),
        );
        let omega = body_omega(&kin, m, b);
        let (what, after) =
            (format!("partial angular velocity of {x}"), format!(" ({}'s components)", b.frame));
        let wt = named_partials(st, &format!("wt_{x}"), &what, &after, &omega, true);
        partials.push((vt, wt));
    }

    // Kane's sums run over *assemblies*: each rigid body with the wheels its frame carries whose
    // centres are fixed relative to its mass centre (a chain of offsets in that frame from a
    // common point), as one body of their total mass at their common mass centre T, with the
    // inertia about T of the parts (each wheel diag(I_d, I_d, I_a) about its axle in the
    // frame's axes, by symmetry) plus the parallel-axis terms sum m_k (|d_k|^2 1 - d_k d_k^T)
    // of the parts' offsets d_k from T; a wheel no body carries is an assembly of its own.
    // Kane's sums over the parts equal the assembly's because sum m_k d_k = 0. A wheel's spin
    // about its axle e adds, with s_i its partial rate and sigma its acceleration at zero
    // independent accelerations (zero for an independent spin),
    // I_a (s_i wt_j.e + s_j wt_i.e + s_i s_j) to M_ij, its spin momentum's rate
    // I_a (sigma e + omega x spin e) to the Euler torque, and -s_i I_a (alpha0.e + sigma) to f_i
    // (the wheel's Euler torque along its axle; omega x I omega has no axial component).
    let mut potential = Atom::num(0);
    for t in assemblies(m) {
        let x = &t.name;
        let total: Atom =
            t.parts.iter().map(|(mass, _, _)| mass.clone()).fold(Atom::num(0), |acc, q| acc + q);
        let total = st.name(&format!("m_{x}"), &format!("mass of assembly {x}"), total);
        let mut e = zero3();
        for (mass, _, o) in &t.parts {
            e = add(&e, &scale(&(mass / &total), o));
        }
        let e = st.name3(
            &format!("e_{x}"),
            &format!("from point {} to assembly {x}'s mass centre ({}'s axes)", t.from, t.frame),
            &e,
        );
        let mut inertia: M3 = [zero3(), zero3(), zero3()];
        for (mass, own, o) in &t.parts {
            let dk = sub(o, &e);
            let dd = dot(&dk, &dk);
            for r in 0..3 {
                for c in 0..3 {
                    let kron = if r == c { dd.clone() } else { Atom::num(0) };
                    inertia[r][c] = &inertia[r][c] + &own[r][c] + mass * (kron - &dk[r] * &dk[c]);
                }
            }
        }
        let axes = ["x", "y", "z"];
        for r in 0..3 {
            for c in r..3 {
                let v = st.name(
                    &format!("I_{x}_{}{}", axes[r], axes[c]),
                    &format!(
                        "entry {}{} of assembly {x}'s inertia about its mass centre ({}'s axes)",
                        axes[r], axes[c], t.frame
                    ),
                    inertia[r][c].clone(),
                );
                inertia[r][c] = v.clone();
                inertia[c][r] = v;
            }
        }
        let rho = kin.up(st, &e, &t.frame, &format!("r_{x}"));
        let centre = kin.rigid(&kin.points[&t.from], &kin.frames[&t.frame], &rho);
        let what = format!("partial velocity of assembly {x}'s mass centre");
        let vt = named_partials(st, &format!("vt_{x}"), &what, "", &centre.velocity, false);
        let a0 = st.name3(
            &format!("a0_{x}"),
            &format!(
                "acceleration of assembly {x}'s mass centre at zero independent accelerations"
            ),
            &add(&centre.acceleration, &velocity_part(&centre.velocity)),
        );
        let local = kin.local[&t.frame].clone();
        let what = format!("partial angular velocity of {}", t.frame);
        let wt = named_partials(
            st,
            &format!("wt_{x}"),
            &what,
            " (its own components)",
            &local.omega,
            false,
        );
        let omega = st.name3(
            &format!("om_{x}"),
            &format!("angular velocity of {} (its own components)", t.frame),
            &local.omega,
        );
        let alpha0 = st.name3(
            &format!("al0_{x}"),
            &format!(
                "angular acceleration of {} at zero independent accelerations (its own components)",
                t.frame
            ),
            &add(&local.alpha, &velocity_part(&local.omega)),
        );
        let mut torque = add(&mv(&inertia, &alpha0), &cross(&omega, &mv(&inertia, &omega)));
        for sp in &t.spins {
            let (s, sigma) = spin_rates(&sp.speed, &independent, &a, &w);
            let axle = sp.axis.unit();
            let rate = var(&sp.speed);
            torque = add(
                &torque,
                &add(
                    &scale(&(&sigma * &sp.axial), &axle),
                    &cross(&omega, &scale(&(&rate * &sp.axial), &axle)),
                ),
            );
            let k = sp.axis.index();
            for i in 0..n {
                for j in i..n {
                    mm[i][j] = &mm[i][j]
                        + &sp.axial * (&s[i] * &wt[j][k] + &s[j] * &wt[i][k] + &s[i] * &s[j]);
                }
                f[i] = &f[i] - &s[i] * &sp.axial * (&alpha0[k] + &sigma);
            }
        }
        let force = st.name3(
            &format!("F_{x}"),
            &format!("gravity less the inertia force m a0 of assembly {x} (working frame)"),
            &sub(&scale(&g, &[Atom::num(0), Atom::num(0), total.clone()]), &scale(&total, &a0)),
        );
        let torque = st.name3(
            &format!("N_{x}"),
            &format!(
                "rate of assembly {x}'s angular momentum about its mass centre at zero independent accelerations ({}'s components)",
                t.frame
            ),
            &torque,
        );
        for i in 0..n {
            for j in i..n {
                mm[i][j] =
                    &mm[i][j] + &total * dot(&vt[i], &vt[j]) + dot(&wt[i], &mv(&inertia, &wt[j]));
            }
            f[i] = &f[i] + dot(&force, &vt[i]) - dot(&torque, &wt[i]);
        }
        potential -= &total * &g * &centre.position[2];
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
                mm[i][j].clone(),
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
                f[i].clone(),
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
