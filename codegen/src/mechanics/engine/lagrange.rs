//! Carvallo's modified Lagrange equations (memoir n° 71–72) on a description: the second route
//! to the equations of motion, from the kinetic energy instead of the accelerations.
//!
//! With the dependent speeds eliminated, the kinetic energy is a quadratic form
//! $T(q, u) = \frac12\sum_X m_X v_X^2 + \omega_X\cdot I_X\omega_X$ in the independent speeds
//! ($v_X = \sum_i \tilde v_{X,i} u_i$). For a true coordinate the equation would be
//! $\frac{d}{dt}\frac{\partial T}{\partial u_k} - \frac{\partial T}{\partial q_k} = Q_k$; for the
//! non-holonomic parameters Carvallo replaces $-\partial T/\partial\nu$ by
//! $-\sum m\,M'\,|\,(\partial M/\partial\nu)'$ (n° 72), which for a rigid body is
//! $m\,v_G\cdot(\tilde v_{G,k})' + \omega\cdot I(\tilde\omega_k)'$, the primes being inertial
//! time derivatives. Here every equation is written that way:
//! $$\frac{\partial^2 T}{\partial u_k\partial u_j}\dot u_j = Q_k \;-\;\Big(\frac{d}{dt}\frac{\partial T}{\partial u_k}\Big)_{\dot u = 0}
//! \;+\;\sum_X m_X v_X\cdot(\tilde v_{X,k})' + \omega_X\cdot I_X(\tilde\omega_{X,k})',$$
//! with gravity's $Q_k = -\sum_q \frac{\partial V}{\partial q}\frac{\partial\dot q}{\partial u_k}$
//! from the potential, and the time derivatives taken by the chain rule through the named
//! quantities ([`super::store::Store::dt`]). Nothing of Kane's accelerations enters: the two
//! routes share only the partial velocities and the torques' virtual power.

use symbolica::atom::{Atom, AtomCore};

use super::kane::Kane;
use super::store::{add, cross, d, dot, mv, scale, zero3, Store, V3};
use super::{Kind, Model};
use crate::cas::var;

/// The modified Lagrange equations: mass matrix and forcing (symbols of the store).
pub struct Lagrange {
    /// $\partial^2 T/\partial u_k\partial u_j$.
    pub m: Vec<Vec<Atom>>,
    /// The right-hand side.
    pub f: Vec<Atom>,
}

/// The independent coordinate whose rate is the speed `u`, if any (an ignorable coordinate's
/// plain term vanishes: the kinetic energy does not depend on it).
fn coordinate_of(m: &Model, u: &str) -> Option<String> {
    m.coordinates
        .iter()
        .find(|c| c.speed() == u && c.kind == Kind::Independent)
        .map(|c| c.name.clone())
}

/// $\mathrm{d}T/\mathrm{d}q = \partial T/\partial q + \sum_d \partial T/\partial q_d\,\partial q_d/\partial q$,
/// the dependent coordinates $q_d$ following $q$ through the contact heights
/// ($H_{q_d}\,\partial q_d/\partial q = -H_q$); `None` when the heights do not fix the dependent
/// coordinates one to one (their numbers differ, or more than three).
fn plain_term(m: &Model, st: &mut Store, k: &Kane, t: &Atom, q: &str) -> Option<Atom> {
    let dependent: Vec<&str> = m
        .coordinates
        .iter()
        .filter(|c| c.kind == Kind::Dependent)
        .map(|c| c.name.as_str())
        .collect();
    let mut out = st.partial(t, q);
    if dependent.is_empty() {
        return Some(out);
    }
    if dependent.len() != k.heights.len() || dependent.len() > 3 {
        return None;
    }
    let unknowns: Vec<String> = dependent.iter().map(|d| format!("plain_d{d}")).collect();
    let eqs: Vec<Atom> = k
        .heights
        .iter()
        .map(|(_, h)| {
            let mut e = st.partial(h, q);
            for (d, x) in dependent.iter().zip(&unknowns) {
                e += st.partial(h, d) * var(x);
            }
            e
        })
        .collect();
    let names: Vec<&str> = unknowns.iter().map(String::as_str).collect();
    let rates = crate::cas::solve_linear(&eqs, &names);
    for (d, rate) in dependent.iter().zip(rates) {
        out += st.partial(t, d) * rate;
    }
    Some(out.expand())
}

/// Derives the modified Lagrange equations of `m` from Kane's partial velocities `k`; with
/// `plain`, also the plain Lagrange terms `L_q_<speed>` ([`plain_term`]).
pub fn derive(m: &Model, st: &mut Store, k: &Kane, plain: bool) -> Lagrange {
    let n = k.independent.len();
    let u: Vec<Atom> = k.independent.iter().map(|s| var(s)).collect();
    let mut t = Atom::num(0);
    let mut correction = vec![Atom::num(0); n];
    let omega_w = k.kin.frames[&k.kin.working].omega.clone();
    for (b, (vt, wt)) in k.bodies.iter().zip(&k.partials) {
        let mut v = zero3();
        let mut om = zero3();
        for i in 0..n {
            v = add(&v, &scale(&u[i], &vt[i]));
            om = add(&om, &scale(&u[i], &wt[i]));
        }
        t += (&b.mass * dot(&v, &v) + dot(&om, &mv(&b.inertia, &om))) / Atom::num(2);
        // The components' frame turns with it: the inertial derivative of a vector given in it
        // is the derivative of the components plus (its angular velocity) x (the vector).
        let frame_omega =
            k.kin.down(st, &k.kin.frames[&b.frame].omega, &b.frame, &format!("omf_{}", b.name));
        for kk in 0..n {
            let vt_dot: V3 = add(&vt[kk].clone().map(|c| st.dt(&c)), &cross(&omega_w, &vt[kk]));
            let wt_dot: V3 = add(&wt[kk].clone().map(|c| st.dt(&c)), &cross(&frame_omega, &wt[kk]));
            correction[kk] =
                &correction[kk] + &b.mass * dot(&v, &vt_dot) + dot(&om, &mv(&b.inertia, &wt_dot));
        }
    }
    let t = t.expand();
    // Gravity from the potential: dq/dt per unit u_k is 1 for the coordinate whose rate u_k is,
    // A[qd][k] for a dependent coordinate.
    let mut q_grav = vec![Atom::num(0); n];
    for c in m.coordinates.iter().filter(|c| matches!(c.kind, Kind::Independent | Kind::Dependent))
    {
        let dv = st.partial(&k.potential, &c.name);
        if dv.is_zero() {
            continue;
        }
        let speed = c.speed();
        for kk in 0..n {
            let rate = if k.independent[kk] == speed {
                Atom::num(1)
            } else if let Some(a) = k.a.get(&speed) {
                a[kk].clone()
            } else {
                Atom::num(0)
            };
            q_grav[kk] = &q_grav[kk] - &dv * rate;
        }
    }
    let mut msym = vec![vec![Atom::num(0); n]; n];
    let mut fsym = Vec::new();
    for kk in 0..n {
        let p = d(&t, &k.independent[kk]).expand();
        // Both halves of the symmetric matrix get the entry's symbol.
        #[allow(clippy::needless_range_loop)]
        for j in kk..n {
            let s = st.put(
                &format!("L_M_{}_{}", k.independent[kk], k.independent[j]),
                &format!(
                    "d^2 T / d {} d {} (modified Lagrange)",
                    k.independent[kk], k.independent[j]
                ),
                d(&p, &k.independent[j]).expand(),
            );
            msym[kk][j] = s.clone();
            msym[j][kk] = s;
        }
        let u_k = &k.independent[kk];
        let pdot = st.dt(&p);
        let pdot = st.put(
            &format!("L_p_{u_k}"),
            &format!("(d/dt dT/d{u_k}) at vanishing accelerations: the momentum's derivative of the modified Lagrange equation of {u_k}"),
            pdot,
        );
        let corr = st.put(
            &format!("L_c_{u_k}"),
            &format!("Carvallo's term sum m v.(dv/d{u_k})' + w.I(dw/d{u_k})' of the equation of {u_k} (n° 72), which replaces dT/dq"),
            correction[kk].expand(),
        );
        if let Some(q) = coordinate_of(m, u_k).filter(|_| plain) {
            // The plain Lagrange term dT/dq of the coordinate whose rate u_k is (the dependent
            // coordinates following it through the contact heights), for comparison only.
            if let Some(dtdq) = plain_term(m, st, k, &t, &q) {
                let _ = st.put(
                    &format!("L_q_{u_k}"),
                    &format!("dT/d{q} with the dependent coordinates following through the contact heights: the plain Lagrange term Carvallo's replaces (for comparison)"),
                    dtdq,
                );
            }
        }
        let rhs = &q_grav[kk] + &k.torque_forces[kk] - pdot + corr;
        fsym.push(st.put(
            &format!("L_f_{}", k.independent[kk]),
            &format!("right-hand side of the modified Lagrange equation of {}", k.independent[kk]),
            rhs.expand(),
        ));
    }
    Lagrange { m: msym, f: fsym }
}
