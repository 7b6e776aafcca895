//! The exact linearisation of the Carvallo–Whipple bicycle about upright straight running at
//! speed $v$, by Kane's method truncated at first order (dynamics) and the potential energy at
//! second order (gravity).
//!
//! Configuration (axes of the 2007 benchmark: x forward, y right, z down). The rear contact P
//! moves with the forward speed $v$ along the heading ψ, $P' = v(\cos\psi, \sin\psi, 0)$
//! (the rear wheel's rolling, checked below). The rear frame B has the orientation
//! $R_B = R_z(\psi) R_x(\varphi) R_y(\theta_B)$ (yaw, lean, pitch); the rear wheel centre is
//! $C_R = P + R_z(\psi)R_x(\varphi)(0, 0, -r_R)$; the front frame H turns by δ about the steer
//! axis $s = (\sin\lambda, 0, \cos\lambda)$ of B through the point $(w + c, 0, 0)$ of the
//! reference configuration: $R_H = R_B\, R_y(\lambda) R_z(\delta) R_y(-\lambda)$. The front
//! contact is $C_F + r_F\,d$ with $d$ the unit projection of the vertical on the front wheel's
//! plane; its height vanishing is the holonomic constraint that fixes the pitch $\theta_B$.
//!
//! Small quantities carry the bookkeeping symbol ε (see [`crate::mechanics::series`]). At first order the
//! pitch, which the constraint makes of second order, drops out of the velocities; the yaw rate
//! and the front wheel's spin perturbation follow from the front wheel's rolling without
//! slipping; the equations for the independent speeds φ', δ' are Kane's
//! $\sum_i m_i\,a_i\cdot\partial v_i/\partial u_r + \dot H_i\cdot\partial\omega_i/\partial u_r +
//! \partial V/\partial q_r = T_r$ (the generalised inertia force is a product of first-order
//! accelerations and zeroth-order partial velocities, the inertia forces of the reference motion
//! vanishing). Gravity enters through the potential energy $V(\varphi, \delta)$ at second order
//! with the pitch eliminated by the constraint, so $g K_0$ is its Hessian.

use symbolica::atom::{Atom, AtomCore};

use crate::cas::var;
use crate::cas::{solve_linear, subst};
use crate::mechanics::series::{
    add, coefficients, cross, dot, eps, inertia, map3, mm, mv, rot_x, rot_y, rot_z, scale, sub,
    transpose, trunc, v3, M3, V3,
};

/// Stand-in symbol for $\sin\lambda$.
pub const SIN_LAMBDA: &str = "sin_lambda";
/// Stand-in symbol for $\cos\lambda$.
pub const COS_LAMBDA: &str = "cos_lambda";

/// The state symbols: lean, steer and their first and second time derivatives.
pub const Q: [&str; 2] = ["phi", "delta"];
/// First derivatives of [`Q`].
pub const QD: [&str; 2] = ["phid", "deltad"];
/// Second derivatives of [`Q`].
pub const QDD: [&str; 2] = ["phidd", "deltadd"];

pub(super) fn p(name: &str) -> Atom {
    var(name)
}

/// Time derivative along the perturbed motion (chain rule on the small symbols; the parameters
/// and the speed $v$ are constant).
pub fn dt(e: &Atom) -> Atom {
    let rules = [
        ("phi", "phid"),
        ("phid", "phidd"),
        ("delta", "deltad"),
        ("deltad", "deltadd"),
        ("psi", "psid"),
        ("psid", "psidd"),
        ("fw", "fwd"),
    ];
    let mut out = Atom::num(0);
    for (x, rate) in rules {
        let sym = p(x).get_symbol().expect("symbol");
        if e.contains_symbol(sym) {
            out += e.derivative(sym) * p(rate);
        }
    }
    out
}

fn dt3(a: &V3) -> V3 {
    map3(a, dt)
}

/// The steer rotation $R_y(\lambda) R_z(\delta) R_y(-\lambda)$ with the given sine and cosine
/// of δ.
fn steer(sd: &Atom, cd: &Atom, n: u32) -> M3 {
    steer_with(&p, sd, cd, n)
}

/// [`steer`] with the parameters (here the stand-ins of $\sin\lambda$, $\cos\lambda$) given by
/// `prm`.
pub(super) fn steer_with(prm: &dyn Fn(&str) -> Atom, sd: &Atom, cd: &Atom, n: u32) -> M3 {
    let (sl, cl) = (prm(SIN_LAMBDA), prm(COS_LAMBDA));
    let a = mm(&rot_y(&sl, &cl), &rot_z(sd, cd), n);
    mm(&a, &rot_y(&(-&sl), &cl), n)
}

/// Positions, relative to the rear contact P, of the rear wheel centre, B's and H's mass
/// centres and the front wheel centre, and the orientations of the wheel planes and frames.
pub(super) struct Geometry {
    pub(super) c_r: V3,
    pub(super) b: V3,
    pub(super) h: V3,
    pub(super) c_f: V3,
    /// Rear wheel plane (no spin) $R_z R_x$.
    pub(super) r_plane: M3,
    /// Rear frame.
    pub(super) r_b: M3,
    /// Front frame (also the front wheel plane).
    pub(super) r_h: M3,
}

fn geometry(r_plane: M3, r_b: M3, steer_m: &M3, n: u32) -> Geometry {
    geometry_with(&p, r_plane, r_b, steer_m, n)
}

/// [`geometry`] with the parameters given by `prm`.
pub(super) fn geometry_with(
    prm: &dyn Fn(&str) -> Atom,
    r_plane: M3,
    r_b: M3,
    steer_m: &M3,
    n: u32,
) -> Geometry {
    let p = prm;
    let z = Atom::num(0);
    let (w, c, rr, rf) = (p("w"), p("c"), p("rR"), p("rF"));
    let c_r = mv(&r_plane, &v3(z.clone(), z.clone(), -&rr), n);
    let r_h = mm(&r_b, steer_m, n);
    // Steer-axis point relative to the rear axle, in the reference configuration.
    let a0 = v3(&w + &c, z.clone(), rr.clone());
    let front = |x: V3| -> V3 {
        let rel = mv(steer_m, &sub(&x, &a0), n);
        add(&c_r, &mv(&r_b, &add(&a0, &rel), n))
    };
    let b = add(&c_r, &mv(&r_b, &v3(p("xB"), z.clone(), &p("zB") + &rr), n));
    let h = front(v3(p("xH"), z.clone(), &p("zH") + &rr));
    let c_f = front(v3(w.clone(), z, &rr - &rf));
    Geometry { c_r, b, h, c_f, r_plane, r_b, r_h }
}

/// The unit vertical's projection on the plane with normal `axle` (first order in the tilt is
/// exact up to second order in ε: the normalisation is $1 + O(\varepsilon^2)$).
fn down_in_plane_first_order(axle: &V3) -> V3 {
    let down = v3(Atom::num(0), Atom::num(0), Atom::num(1));
    sub(&down, &scale(&axle[2], axle))
}

/// The holonomic contact constraint at second order and the potential energy.
pub struct Statics {
    /// Coefficient of ε in the front contact's height (vanishes: the pitch is of second order).
    pub constraint_first_order: Atom,
    /// The pitch $\theta_B = \varepsilon^2\,\theta_2$ solved from the constraint, as $\theta_2$.
    pub pitch2: Atom,
    /// Coefficient of ε in $V/g$ (vanishes: upright is an equilibrium).
    pub potential_first_order: Atom,
    /// $K_0 = \partial^2 (V/g) / \partial q^2$, by rows.
    pub k0: [[Atom; 2]; 2],
}

/// Second-order statics: the pitch from the contact constraint and $K_0$.
pub fn statics() -> Statics {
    let n = 2;
    let e = eps();
    let half = Atom::num(1) / Atom::num(2);
    let small_sin = |x: &str| &e * p(x);
    let small_cos = |x: &str| Atom::num(1) - &half * &e.pow(Atom::num(2)) * p(x).pow(Atom::num(2));
    let rx = rot_x(&small_sin("phi"), &small_cos("phi"));
    let pitch_s = e.pow(Atom::num(2)) * p("th2");
    let r_b = mm(&rx, &rot_y(&pitch_s, &Atom::num(1)), n);
    let st = steer(&small_sin("delta"), &small_cos("delta"), n);
    let geo = geometry(rx, r_b, &st, n);
    let axle = mv(&geo.r_h, &v3(Atom::num(0), Atom::num(1), Atom::num(0)), n);
    // Height (z down) of the front contact: C_F,z + r_F sqrt(1 - a_z^2).
    let az2 = trunc(&(&axle[2] * &axle[2]), n);
    let height = trunc(&(&geo.c_f[2] + p("rF") * (Atom::num(1) - &half * az2)), n);
    let hc = coefficients(&height, n);
    let th2_sym = p("th2").get_symbol().expect("symbol");
    let slope = hc[2].derivative(th2_sym).expand();
    let rest = subst(&hc[2], "th2", &Atom::num(0));
    let pitch2 = (-rest / slope).expand();
    // V/g = -sum m z (z down).
    let v_over_g = -(p("mR") * &geo.c_r[2]
        + p("mB") * &geo.b[2]
        + p("mH") * &geo.h[2]
        + p("mF") * &geo.c_f[2]);
    let vc = coefficients(&v_over_g, n);
    let v2 = subst(&vc[2], "th2", &pitch2).expand();
    let d2 = |a: &str, b: &str| {
        let sa = p(a).get_symbol().expect("symbol");
        let sb = p(b).get_symbol().expect("symbol");
        v2.derivative(sa).derivative(sb).expand()
    };
    Statics {
        constraint_first_order: hc[1].clone(),
        pitch2,
        potential_first_order: vc[1].clone(),
        k0: [[d2("phi", "phi"), d2("phi", "delta")], [d2("delta", "phi"), d2("delta", "delta")]],
    }
}

/// The first-order dynamics.
pub struct Dynamics {
    /// Rear wheel contact point's velocity at first order (vanishes: rolling without slipping
    /// is satisfied by $P' = v(\cos\psi, \sin\psi, 0)$, $\theta_R' = -v/r_R$).
    pub rear_slip: V3,
    /// Front wheel contact point's velocity at orders 0 and 1 after solving for the yaw rate
    /// and the front spin perturbation (vanishes).
    pub front_slip: V3,
    /// The yaw rate ψ' (first order) from the front wheel's rolling.
    pub yaw_rate: Atom,
    /// First-order perturbation of the front wheel's spin rate (ε times this).
    pub front_spin: Atom,
    /// The generalised inertia forces (Kane) for φ' and δ', first order, ε set to 1.
    pub inertia_forces: [Atom; 2],
    /// $M$ (coefficients of the accelerations).
    pub m: [[Atom; 2]; 2],
    /// $C_1$ (coefficients of the rates divided by $v$).
    pub c1: [[Atom; 2]; 2],
    /// $K_2$ (coefficients of the angles divided by $v^2$).
    pub k2: [[Atom; 2]; 2],
}

/// First-order kinematics and Kane's equations for the lean and steer speeds.
pub fn dynamics() -> Dynamics {
    dynamics_with(&p)
}

/// [`dynamics`] with the parameters (and the stand-ins of $\sin\lambda$, $\cos\lambda$) given
/// by `prm`: symbols, or exact numbers for a fast evaluation at a rational parameter point (the
/// state, the rates and $v$ stay symbols).
pub fn dynamics_with(prm: &dyn Fn(&str) -> Atom) -> Dynamics {
    let p = |name: &str| -> Atom {
        if super::PARAMS.contains(&name) || name == SIN_LAMBDA || name == COS_LAMBDA {
            prm(name)
        } else {
            var(name)
        }
    };
    let n = 1;
    let e = eps();
    let one = Atom::num(1);
    let z = Atom::num(0);
    let v = p("v");
    let (sy, sp, sd) = (&e * p("psi"), &e * p("phi"), &e * p("delta"));
    let rz = rot_z(&sy, &one);
    let r_plane = mm(&rz, &rot_x(&sp, &one), n);
    let st = steer_with(&p, &sd, &one, n);
    let geo = geometry_with(&p, r_plane.clone(), r_plane.clone(), &st, n);
    let ex = v3(one.clone(), z.clone(), z.clone());
    let ey = v3(z.clone(), one.clone(), z.clone());
    let ez = v3(z.clone(), z.clone(), one.clone());
    // Angular velocities (composition of the elementary rotations; the pitch rate is of
    // second order).
    let w_b = add(&scale(&(&e * p("psid")), &ez), &mv(&rz, &scale(&(&e * p("phid")), &ex), n));
    let w_r = add(&w_b, &mv(&geo.r_plane, &scale(&(-(&v / p("rR"))), &ey), n));
    let axis = v3(p(SIN_LAMBDA), z.clone(), p(COS_LAMBDA));
    let w_h = add(&w_b, &mv(&geo.r_b, &scale(&(&e * p("deltad")), &axis), n));
    let spin_f = -(&v / p("rF")) + &e * p("fw");
    let w_f = add(&w_h, &mv(&geo.r_h, &scale(&spin_f, &ey), n));
    // Rear contact velocity.
    let p_dot = v3(v.clone(), &v * &sy, z.clone());
    let vel = |x: &V3| -> V3 { map3(&add(&p_dot, &dt3(x)), |c| trunc(c, n)) };
    let v_cr = vel(&geo.c_r);
    let rear_slip = add(&v_cr, &cross(&w_r, &scale(&Atom::num(-1), &geo.c_r), n));
    // Front contact: C_F + r_F d, material velocity v_CF + w_F x (r_F d) = 0.
    let axle_f = mv(&geo.r_h, &ey, n);
    let d = scale(&p("rF"), &down_in_plane_first_order(&axle_f));
    let v_cf = vel(&geo.c_f);
    let slip_f = add(&v_cf, &cross(&w_f, &d, n));
    let at_psi0 = |x: &Atom| subst(x, "psi", &Atom::num(0));
    let first = |x: &Atom| coefficients(&at_psi0(x), 1)[1].clone();
    let sol = solve_linear(&[first(&slip_f[0]), first(&slip_f[1])], &["psid", "fw"]);
    let (yaw_rate, front_spin) = (sol[0].clone(), sol[1].clone());
    let yaw_rate_d = dt(&yaw_rate);
    let front_spin_d = dt(&front_spin);
    let close = |x: &Atom| -> Atom {
        let a = subst(x, "psidd", &yaw_rate_d);
        let a = subst(&a, "fwd", &front_spin_d);
        let a = subst(&a, "psid", &yaw_rate);
        let a = subst(&a, "fw", &front_spin);
        trunc(&at_psi0(&a), n)
    };
    let close3 = |x: &V3| map3(x, close);
    let front_slip = close3(&slip_f);
    // Accelerations of the mass centres, P'' = (0, v psi', 0) at first order.
    let p_ddot = v3(z.clone(), &v * &e * p("psid"), z.clone());
    let acc = |x: &V3| -> V3 { close3(&add(&p_ddot, &dt3(&dt3(x)))) };
    // Angular momenta about the mass centres in the ground frame and their derivatives.
    let world = |r: &M3, i: &M3| mm(&mm(r, i, n), &transpose(r), n);
    let i_r = inertia(p("IRxx"), p("IRyy"), p("IRxx"), z.clone());
    let i_b = inertia(p("IBxx"), p("IByy"), p("IBzz"), p("IBxz"));
    let i_h = inertia(p("IHxx"), p("IHyy"), p("IHzz"), p("IHxz"));
    let i_f = inertia(p("IFxx"), p("IFyy"), p("IFxx"), z.clone());
    let bodies: [(Atom, V3, M3, V3); 4] = [
        (p("mR"), geo.c_r.clone(), world(&geo.r_plane, &i_r), w_r),
        (p("mB"), geo.b.clone(), world(&geo.r_b, &i_b), w_b),
        (p("mH"), geo.h.clone(), world(&geo.r_h, &i_h), w_h),
        (p("mF"), geo.c_f.clone(), world(&geo.r_h, &i_f), w_f),
    ];
    let partial = |x: &V3, u: &str| -> V3 {
        let s = p(u).get_symbol().expect("symbol");
        map3(&close3(x), |c| subst(&c.derivative(s), "eps", &one).expand())
    };
    let mut forces = [Atom::num(0), Atom::num(0)];
    for (mass, pos, iw, om) in &bodies {
        let a = acc(pos);
        let hdot = close3(&dt3(&mv(iw, om, n)));
        let vx = vel(pos);
        for (r, u) in QD.iter().enumerate() {
            let pv = partial(&vx, u);
            let pw = partial(om, u);
            forces[r] += mass * &dot(&a, &pv, n) + dot(&hdot, &pw, n);
        }
    }
    // Every term is a scalar product truncated at order n (`dot`), so the sum is too: setting
    // ε = 1 needs no second truncation (which would expand the whole sum once more).
    let forces = forces.map(|f| subst(&f, "eps", &one).expand());
    let coef = |f: &Atom, x: &str, div: &Atom| {
        let s = p(x).get_symbol().expect("symbol");
        (f.derivative(s) / div).expand()
    };
    let v2 = v.pow(Atom::num(2));
    let mat = |x: &[&str; 2], div: &Atom| {
        [
            [coef(&forces[0], x[0], div), coef(&forces[0], x[1], div)],
            [coef(&forces[1], x[0], div), coef(&forces[1], x[1], div)],
        ]
    };
    Dynamics {
        rear_slip,
        front_slip,
        yaw_rate,
        front_spin,
        m: mat(&QDD, &one),
        c1: mat(&QD, &v),
        k2: mat(&Q, &v2),
        inertia_forces: forces,
    }
}

/// Returns `Σ_j m[r][j] x_j` for the symbol names `x`.
pub fn apply(m: &[[Atom; 2]; 2], x: &[&str; 2], r: usize) -> Atom {
    &m[r][0] * p(x[0]) + &m[r][1] * p(x[1])
}
