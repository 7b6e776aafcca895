//! Carvallo's modified Lagrange equations for the lean and steer of the Carvallo–Whipple
//! bicycle, at the linear level, as an independent route to the equations of [`super::linear`].
//!
//! With the rolling constraints substituted, lean φ and steer δ are not true Lagrangian
//! coordinates (the yaw, the contact positions and the front wheel's rotation depend on the
//! history of the motion), and Carvallo (memoir n° 72) replaces $-\partial T/\partial q$ by
//! $-\sum m\,M'\,|\,(\partial M/\partial q)'$, where $\partial M/\partial q$ is the displacement
//! of the point M when q alone varies with the constraints obeyed (its partial velocity). For a
//! rigid body of mass centre G the sum is $m\,v_G\cdot(\partial v_G/\partial q')' +
//! (I\omega)\cdot(\partial\omega/\partial q')'$ (the rest, $\sum m\,(\omega\times\rho)\cdot
//! (\Omega_q\times(\omega\times\rho))$, vanishes). So the equation of q is
//! $$\frac{d}{dt}\frac{\partial T^*}{\partial q'} - \sum_{\text{bodies}}\Bigl[m\,v_G\cdot
//! \Bigl(\frac{\partial v_G}{\partial q'}\Bigr)' + I\omega\cdot\Bigl(\frac{\partial\omega}
//! {\partial q'}\Bigr)'\Bigr] = Q_q$$
//! with $T^*$ the kinetic energy with the constraints substituted. At first order in the
//! equations $T^*$ is needed at second order, hence the kinematics at second order: the frame
//! pitch (second order, from the contact constraint, see [`super::linear::statics`]), the yaw
//! rate and the front wheel's spin at second order from the front wheel's rolling, and the
//! rear wheel's rolling checked at second order. The inertial part obtained this way is
//! compared exactly with Kane's (the generalised inertia forces of [`super::linear::dynamics`]).

use symbolica::atom::{Atom, AtomCore};

use super::linear::{dt, geometry_with, steer_with};
use crate::cas::{solve_linear, subst};
use crate::mechanics::series::{
    add, coefficients, cross, dot, eps, inertia, map3, mm, mv, rot_x, rot_y, rot_z, scale,
    transpose, trunc, v3, M3, V3,
};

/// The outcome of the second-order route.
pub struct CarvalloForm {
    /// The rear wheel contact point's velocity at second order (vanishes).
    pub rear_slip: V3,
    /// The front wheel contact point's velocity at second order after solving (vanishes).
    pub front_slip: V3,
    /// The inertial parts of Carvallo's equations for φ and δ at first order (ε set to 1).
    pub equations: [Atom; 2],
    /// The plain Lagrange expressions $\frac{d}{dt}\partial T^*/\partial q' - \partial T^*/\partial q$
    /// at first order, which ignore the constraints' history (for comparison).
    pub plain: [Atom; 2],
    /// The first term of [`CarvalloForm::equations`] alone, $\frac{d}{dt}\partial T^*/\partial q'$
    /// at first order (the equations minus these are the correction terms
    /// $-\sum m\,M'\,|\,(\partial M/\partial q)'$).
    pub momentum_terms: [Atom; 2],
}

/// Builds Carvallo's equations with the pitch $\theta_B = \varepsilon^2$ `pitch2`, the
/// parameters (and the stand-ins of $\sin\lambda$, $\cos\lambda$) being given by `prm`
/// (symbols or exact numbers; `pitch2` must already use the same values).
pub fn carvallo_form(prm: &dyn Fn(&str) -> Atom, pitch2: &Atom) -> CarvalloForm {
    let p = |name: &str| -> Atom {
        if super::PARAMS.contains(&name)
            || name == super::linear::SIN_LAMBDA
            || name == super::linear::COS_LAMBDA
        {
            prm(name)
        } else {
            crate::cas::var(name)
        }
    };
    let n = 2;
    let e = eps();
    let one = Atom::num(1);
    let z = Atom::num(0);
    let v = p("v");
    let half = Atom::num(1) / Atom::num(2);
    let e2 = e.pow(Atom::num(2));
    let s_of = |x: &str| &e * p(x);
    let c_of = |x: &str| Atom::num(1) - &half * &e2 * p(x).pow(Atom::num(2));
    let rz = rot_z(&s_of("psi"), &c_of("psi"));
    let r_plane = mm(&rz, &rot_x(&s_of("phi"), &c_of("phi")), n);
    let theta_b = &e2 * pitch2;
    let r_b = mm(&r_plane, &rot_y(&theta_b, &one), n);
    let st = steer_with(&p, &s_of("delta"), &c_of("delta"), n);
    let geo = geometry_with(&p, r_plane.clone(), r_b, &st, n);
    let ex = v3(one.clone(), z.clone(), z.clone());
    let ey = v3(z.clone(), one.clone(), z.clone());
    let ez = v3(z.clone(), z.clone(), one.clone());
    let pitch_rate = trunc(&dt(&theta_b), n);
    let w_plane = add(&scale(&(&e * p("psid")), &ez), &mv(&rz, &scale(&(&e * p("phid")), &ex), n));
    let w_b = add(&w_plane, &mv(&r_plane, &scale(&pitch_rate, &ey), n));
    let w_r = add(&w_plane, &mv(&r_plane, &scale(&(-(&v / p("rR"))), &ey), n));
    let axis = v3(p(super::linear::SIN_LAMBDA), z.clone(), p(super::linear::COS_LAMBDA));
    let w_h = add(&w_b, &mv(&geo.r_b, &scale(&(&e * p("deltad")), &axis), n));
    let spin_f = -(&v / p("rF")) + &e * p("fw");
    let w_f = add(&w_h, &mv(&geo.r_h, &scale(&spin_f, &ey), n));
    let p_dot = v3(&v * c_of("psi"), &v * s_of("psi"), z.clone());
    let vel = |x: &V3| -> V3 { map3(&add(&p_dot, &map3(x, dt)), |c| trunc(c, n)) };
    let rear_slip_raw = add(&vel(&geo.c_r), &cross(&w_r, &scale(&Atom::num(-1), &geo.c_r), n));
    // Front contact: d = z (1 + a_z^2 / 2) - a_z a, exact to second order.
    let axle = mv(&geo.r_h, &ey, n);
    let az = axle[2].clone();
    let d = add(
        &scale(&(Atom::num(1) + &half * &az * &az), &ez),
        &scale(&Atom::num(-1), &scale(&az, &axle)),
    );
    let d = scale(&p("rF"), &map3(&d, |c| trunc(c, n)));
    let slip_f = add(&vel(&geo.c_f), &cross(&w_f, &d, n));
    let at_psi0 = |x: &Atom| subst(x, "psi", &Atom::num(0));
    // Order 1: psid = p1, fw = f1; order 2: psid = p1 + eps p2, fw = f1 + eps f2.
    let c1 = |x: &Atom| coefficients(&at_psi0(x), 2)[1].clone();
    let s1 = solve_linear(&[c1(&slip_f[0]), c1(&slip_f[1])], &["psid", "fw"]);
    let trial = |x: &Atom| {
        let a = subst(x, "psid", &(&s1[0] + &e * p("p2")));
        subst(&a, "fw", &(&s1[1] + &e * p("f2")))
    };
    let c2 = |x: &Atom| coefficients(&at_psi0(&trial(x)), 2)[2].clone();
    let s2 = solve_linear(&[c2(&slip_f[0]), c2(&slip_f[1])], &["p2", "f2"]);
    let yaw = &s1[0] + &e * &s2[0];
    let spin = &s1[1] + &e * &s2[1];
    let close = |x: &Atom| -> Atom {
        let a = subst(x, "psid", &yaw);
        trunc(&subst(&a, "fw", &spin), n)
    };
    let close3 = |x: &V3| map3(x, close);
    let front_slip = map3(&close3(&slip_f), at_psi0);
    let rear_slip = map3(&close3(&rear_slip_raw), at_psi0);
    let world = |r: &M3, i: &M3| mm(&mm(r, i, n), &transpose(r), n);
    let zz = Atom::num(0);
    let bodies: [(Atom, V3, M3, V3); 4] = [
        (
            p("mR"),
            geo.c_r.clone(),
            world(&geo.r_plane, &inertia(p("IRxx"), p("IRyy"), p("IRxx"), zz.clone())),
            w_r,
        ),
        (
            p("mB"),
            geo.b.clone(),
            world(&geo.r_b, &inertia(p("IBxx"), p("IByy"), p("IBzz"), p("IBxz"))),
            w_b,
        ),
        (
            p("mH"),
            geo.h.clone(),
            world(&geo.r_h, &inertia(p("IHxx"), p("IHyy"), p("IHzz"), p("IHxz"))),
            w_h,
        ),
        (
            p("mF"),
            geo.c_f.clone(),
            world(&geo.r_h, &inertia(p("IFxx"), p("IFyy"), p("IFxx"), zz)),
            w_f,
        ),
    ];
    // d/dt then close again (the derivative of psi brings psid back).
    let ddt = |x: &Atom| close(&dt(x));
    // Partial derivative by a rate (which carries one eps), divided by eps.
    let partial = |x: &Atom, u: &str| -> Atom {
        let s = p(u).get_symbol().expect("symbol");
        trunc(&(x.derivative(s) / &e).expand(), 1)
    };
    let mut t_star = Atom::num(0);
    let mut states: Vec<(Atom, V3, V3, V3)> = Vec::new();
    for (mass, pos, iw, om) in &bodies {
        let vg = close3(&vel(pos));
        let omc = close3(om);
        let h = mv(iw, &omc, n);
        t_star += &half * (mass * &dot(&vg, &vg, n) + dot(&omc, &h, n));
        states.push((mass.clone(), vg, omc, h));
    }
    let t_star = trunc(&t_star, n);
    let mut equations = [Atom::num(0), Atom::num(0)];
    let mut plain = [Atom::num(0), Atom::num(0)];
    let mut momentum_terms = [Atom::num(0), Atom::num(0)];
    for (r, u) in super::linear::QD.iter().enumerate() {
        let momentum = partial(&t_star, u);
        let mut eq = ddt(&momentum);
        let first = coefficients(&at_psi0(&trunc(&eq, 1)), 1);
        momentum_terms[r] = &first[1] + &first[0];
        let lag = &eq - partial(&t_star, super::linear::Q[r]);
        plain[r] = coefficients(&at_psi0(&trunc(&lag, 1)), 1)[1].clone();
        for (mass, vg, omc, h) in &states {
            let pv = map3(vg, |c| partial(c, u));
            let pw = map3(omc, |c| partial(c, u));
            let dpv = map3(&pv, ddt);
            let dpw = map3(&pw, ddt);
            eq = eq - mass * dot(vg, &dpv, 2) - dot(h, &dpw, 2);
        }
        let first = coefficients(&at_psi0(&trunc(&eq, 1)), 1);
        equations[r] = first[1].clone();
        // The zeroth order must vanish too; keep it visible by adding it (it is checked to be 0
        // through the comparison, since Kane's forces have no zeroth-order term).
        equations[r] = &equations[r] + &first[0];
    }
    CarvalloForm { rear_slip, front_slip, equations, plain, momentum_terms }
}
