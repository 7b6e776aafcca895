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

/// Derives the modified Lagrange equations of `m` from Kane's partial velocities `k`.
pub fn derive(m: &Model, st: &mut Store, k: &Kane) -> Lagrange {
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
        let pdot = st.dt(&p);
        let rhs = &q_grav[kk] + &k.torque_forces[kk] - pdot + &correction[kk];
        fsym.push(st.put(
            &format!("L_f_{}", k.independent[kk]),
            &format!("right-hand side of the modified Lagrange equation of {}", k.independent[kk]),
            rhs.expand(),
        ));
    }
    Lagrange { m: msym, f: fsym }
}
