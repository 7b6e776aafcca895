//! The nonlinear equations of motion of the Carvallo–Whipple bicycle (rear wheel R, rear frame
//! with rider B, front frame H, front wheel F; knife-edge wheels rolling without slipping on
//! flat ground), with the 25 parameters of the 2007 benchmark (Meijaard, Papadopoulos, Ruina,
//! Schwab, Proc. R. Soc. A 463, Table 1) kept as symbols, by Kane's method.
//!
//! Configuration (benchmark axes: x forward, y right, z down): the rear contact $P = (x, y, 0)$,
//! the yaw ψ, the lean φ, the rear frame's pitch θ (zero in the benchmark's reference
//! configuration), the rear wheel's rotation $\theta_R$ relative to the rear frame, the steer δ
//! and the front wheel's rotation $\theta_F$ relative to the front frame. The rear frame has the
//! orientation $R_B = R_z(\psi)R_x(\varphi)R_y(\theta)$ and the front frame
//! $R_H = R_B R_y(\lambda)R_z(\delta)R_y(-\lambda)$, as in [`crate::derive::whipple`]'s linearisation.
//! Every vector is written in the yawed frame $R_z(\psi)$ (the equations do not depend on ψ,
//! $x$, $y$, $\theta_R$, $\theta_F$).
//!
//! Constraints. The front contact point's height
//! $h(\varphi, \theta, \delta) = z_{C_F} + r_F n_F$, $n_F = \sqrt{1 - a_z^2}$ with $a$ the front
//! axle, vanishes (holonomic; solved for the pitch by Newton at run time with the generated
//! $\partial h/\partial\theta$). The rear wheel's rolling gives
//! $\dot P = -r_R(\dot\theta + \dot\theta_R)(\cos\psi, \sin\psi, 0)$. The front wheel's material
//! contact point has zero velocity; its components along the vertical, along the horizontal
//! projection $(a_x, a_y, 0)$ of the axle and along $(a_y, -a_x, 0)$ are triangular in the
//! dependent rates: they give, one after the other, the pitch rate, the yaw rate and the front
//! wheel's rate as linear forms in the independent speeds $u = (\dot\varphi, \dot\delta,
//! \dot\theta_R)$ (the zero coefficients that make it triangular are checked exactly).
//!
//! Equations. $M_3 \dot u = f_3$ with
//! $M_{3,ij} = \sum_X m_X \tilde v_{X,i}\cdot\tilde v_{X,j} + \tilde\omega_{X,i}\cdot I_X
//! \tilde\omega_{X,j}$ and $f_{3,i} = \sum_X m_X (g\hat z - a^0_X)\cdot\tilde v_{X,i} - (I_X
//! \alpha^0_X + \omega_X\times I_X\omega_X)\cdot\tilde\omega_{X,i}$, where
//! $\tilde v$, $\tilde\omega$ are the non-holonomic partial velocities and $a^0$, $\alpha^0$ the
//! accelerations at $\dot u = 0$ (with the dependent accelerations' velocity parts, from the
//! derivative of the constraint rows). The sums run over two *assemblies*, not the four bodies:
//! each frame with its wheel, whose centre is fixed in it, as one body of their total mass at
//! their mass centre $T$, with the inertia about $T$ of the frame, the wheel (symmetric about its
//! axle, so constant in the frame's axes) and the parallel-axis terms
//! $\sum_k m_k(|d_k|^2 1 - d_k d_k^T)$ of the two masses' offsets $d_k$ from $T$. Kane's sums
//! over the two bodies equal the assembly's because $\sum_k m_k d_k = 0$; each wheel's spin
//! $\dot\theta_W$ about the axle $y$ adds
//! $I_{W,yy}(s_i\tilde\omega_{j,y} + s_j\tilde\omega_{i,y} + s_i s_j)$ to $M_{3,ij}$ ($s_i$ the
//! spin's partial rate) and its Euler torque's terms to $f_3$. This halves the terms of $M_3$ and
//! $f_3$ (1,640 to 1,489 operations; the values agree with the four-body sums at 256 bits).
//! Nothing is inverted symbolically: the runtime solves $M_3$ by LU.
//!
//! The expressions are handed over *factored*: each named intermediate quantity (the sines and
//! cosines, the steer rotation's entries, the front axle's components, the position vectors of the rigid-body chain that gives
//! the mass centres' velocities and accelerations, the constraint coefficients, the dependent
//! rates, the partial velocities, the velocity-part accelerations, ...) is its own formula, and later formulas refer to earlier
//! ones by name (see [`crate::emit::emit_program`]); substituting everything into $M_3$, $f_3$
//! would expand them by orders of magnitude. Outputs also give the total energy and the front
//! contact's position for the ground tracks.

use anyhow::{ensure, Result};
use symbolica::atom::{Atom, AtomCore};

use crate::cas::subst;
use crate::cas::var;
use crate::{Check, Derivation, Formula};

/// Parameter names, in order (those of the `whipple` model).
pub const PARAMS: [&str; 26] = crate::derive::whipple::PARAMS;
/// Input names, in order: lean, pitch, steer, and the independent speeds (lean rate, steer
/// rate, rear wheel rate relative to the rear frame).
pub const INPUTS: [&str; 6] = ["phi", "theta", "delta", "phid", "deltad", "thetaRd"];
/// The independent speeds.
pub const INDEPENDENT: [&str; 3] = ["phid", "deltad", "thetaRd"];
/// The dependent speeds, in the order the triangular constraint rows give them: pitch rate,
/// yaw rate, front wheel rate (relative to the front frame).
pub const DEPENDENT: [&str; 3] = ["thetad", "psid", "thetaFd"];
/// All six speeds: the independent ones, then the dependent ones.
const SPEEDS: [&str; 6] = ["phid", "deltad", "thetaRd", "thetad", "psid", "thetaFd"];
/// The names of the steer rotation's entries.
const RS: [[&str; 3]; 3] =
    [["rS_11", "rS_12", "rS_13"], ["rS_21", "rS_22", "rS_23"], ["rS_31", "rS_32", "rS_33"]];
/// The four bodies: rear wheel, rear frame, front frame, front wheel.
pub const BODIES: [&str; 4] = ["R", "B", "H", "F"];

type V3 = [Atom; 3];
type M3 = [[Atom; 3]; 3];

fn num(n: i64) -> Atom {
    Atom::num(n)
}

fn add(a: &V3, b: &V3) -> V3 {
    [&a[0] + &b[0], &a[1] + &b[1], &a[2] + &b[2]]
}

fn sub(a: &V3, b: &V3) -> V3 {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

fn scale(k: &Atom, a: &V3) -> V3 {
    [k * &a[0], k * &a[1], k * &a[2]]
}

fn dot(a: &V3, b: &V3) -> Atom {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

fn cross(a: &V3, b: &V3) -> V3 {
    [&a[1] * &b[2] - &a[2] * &b[1], &a[2] * &b[0] - &a[0] * &b[2], &a[0] * &b[1] - &a[1] * &b[0]]
}

fn map3(a: &V3, f: impl Fn(&Atom) -> Atom) -> V3 {
    [f(&a[0]), f(&a[1]), f(&a[2])]
}

fn expand3(a: &V3) -> V3 {
    map3(a, |x| x.expand())
}

fn mv(m: &M3, v: &V3) -> V3 {
    [
        (&m[0][0] * &v[0] + &m[0][1] * &v[1] + &m[0][2] * &v[2]).expand(),
        (&m[1][0] * &v[0] + &m[1][1] * &v[1] + &m[1][2] * &v[2]).expand(),
        (&m[2][0] * &v[0] + &m[2][1] * &v[1] + &m[2][2] * &v[2]).expand(),
    ]
}

fn transpose(m: &M3) -> M3 {
    let mut t = m.clone();
    for (r, row) in t.iter_mut().enumerate() {
        for (c, x) in row.iter_mut().enumerate() {
            *x = m[c][r].clone();
        }
    }
    t
}

fn mm(a: &M3, b: &M3) -> M3 {
    let mut out = a.clone();
    for (r, row) in out.iter_mut().enumerate() {
        for (c, x) in row.iter_mut().enumerate() {
            *x = (&a[r][0] * &b[0][c] + &a[r][1] * &b[1][c] + &a[r][2] * &b[2][c]).expand();
        }
    }
    out
}

fn rot_x(s: &Atom, c: &Atom) -> M3 {
    [[num(1), num(0), num(0)], [num(0), c.clone(), -s], [num(0), s.clone(), c.clone()]]
}

fn rot_y(s: &Atom, c: &Atom) -> M3 {
    [[c.clone(), num(0), s.clone()], [num(0), num(1), num(0)], [-s, num(0), c.clone()]]
}

fn rot_z(s: &Atom, c: &Atom) -> M3 {
    [[c.clone(), -s, num(0)], [s.clone(), c.clone(), num(0)], [num(0), num(0), num(1)]]
}

fn inertia(xx: &str, yy: &str, zz: &str, xz: Option<&str>) -> M3 {
    let xz = xz.map(var).unwrap_or_else(|| num(0));
    [[var(xx), num(0), xz.clone()], [num(0), var(yy), num(0)], [xz, num(0), var(zz)]]
}

/// Derivative of `e` with respect to the symbol `name`.
fn d(e: &Atom, name: &str) -> Atom {
    let s = var(name).get_symbol().expect("a symbol");
    if e.contains_symbol(s) {
        e.derivative(s)
    } else {
        num(0)
    }
}

/// Chain rule over the "leaf" symbols: $\sum_k \partial e/\partial \ell_k \cdot r_k$.
fn chain(e: &Atom, rules: &[(&str, Atom)]) -> Atom {
    let mut out = num(0);
    for (leaf, rate) in rules {
        let de = d(e, leaf);
        if !de.is_zero() {
            out += de * rate;
        }
    }
    out.expand()
}

/// The formulas handed over, and the bookkeeping of named intermediates.
struct Named {
    formulas: Vec<Formula>,
}

impl Named {
    /// Records `expr` as the formula `name` and returns the symbol standing for it.
    fn name(&mut self, name: &str, description: &str, expr: Atom) -> Atom {
        self.formulas.push(Formula {
            name: name.to_string(),
            section: "nonlinear".to_string(),
            description: description.to_string(),
            expr,
        });
        var(name)
    }

    /// Records `expr` as the formula `name` (a final output nothing else refers to).
    fn put(&mut self, name: &str, description: &str, expr: Atom) {
        let _ = self.name(name, description, expr);
    }

    fn name3(&mut self, name: &str, description: &str, v: &V3) -> V3 {
        let comps = ["x", "y", "z"];
        [0, 1, 2].map(|k| {
            self.name(
                &format!("{name}_{}", comps[k]),
                &format!("{description}, {} component", comps[k]),
                v[k].clone(),
            )
        })
    }
}

fn check(id: &str, statement: &str, holds: bool, detail: String) -> Check {
    Check {
        section: "nonlinear".to_string(),
        id: id.to_string(),
        statement: statement.to_string(),
        holds,
        detail,
    }
}

/// One body: mass, mass centre relative to P (yawed frame), velocity (yawed frame), angular
/// velocity (in the body's own frame), inertia about the mass centre (body frame).
struct Body {
    name: &'static str,
    mass: Atom,
    velocity: V3,
    omega: V3,
    inertia: M3,
    position: V3,
}

/// Derives the model's formulas and checks.
#[allow(clippy::needless_range_loop)]
pub fn derive() -> Result<Derivation> {
    let mut nm = Named { formulas: Vec::new() };
    let mut checks = Vec::new();
    // Leaves: sines and cosines of the angles.
    let sphi = nm.name("sphi", "sin(phi), lean", var("sin(phi)"));
    let cphi = nm.name("cphi", "cos(phi)", var("cos(phi)"));
    let sth = nm.name("sth", "sin(theta), rear frame pitch", var("sin(theta)"));
    let cth = nm.name("cth", "cos(theta)", var("cos(theta)"));
    let sdel = nm.name("sdel", "sin(delta), steer", var("sin(delta)"));
    let cdel = nm.name("cdel", "cos(delta)", var("cos(delta)"));
    let slam = nm.name("slam", "sin(lambda), steer axis tilt", var("sin(lambda)"));
    let clam = nm.name("clam", "cos(lambda)", var("cos(lambda)"));
    let p = var;
    let (w, c, rr, rf) = (p("w"), p("c"), p("rR"), p("rF"));

    // Orientations (yawed frame) and positions relative to P.
    let r_l = rot_x(&sphi, &cphi);
    let r_b = mm(&r_l, &rot_y(&sth, &cth));
    let r_s = mm(&mm(&rot_y(&slam, &clam), &rot_z(&sdel, &cdel)), &rot_y(&(-&slam), &clam));
    let r_h = mm(&r_b, &r_s);
    // The steer rotation's entries are named (they enter the front frame's angular velocity
    // and position vectors; expanded with the rear frame's they took several hundred
    // operations); their time derivatives come from the chain rule in delta (`rules` below).
    let rs_sym: M3 = [0, 1, 2].map(|i| {
        [0, 1, 2].map(|j| {
            nm.name(
                RS[i][j],
                &format!(
                    "entry ({}, {}) of the steer rotation R_y(lambda) R_z(delta) R_y(-lambda)",
                    i + 1,
                    j + 1
                ),
                r_s[i][j].clone(),
            )
        })
    });
    let c_r = mv(&r_l, &[num(0), num(0), -&rr]);
    let a0 = [&w + &c, num(0), rr.clone()];
    let front = |x: V3| -> V3 {
        let rel = mv(&r_s, &sub(&x, &a0));
        expand3(&add(&c_r, &mv(&r_b, &add(&a0, &rel))))
    };
    let pos_b = expand3(&add(&c_r, &mv(&r_b, &[p("xB"), num(0), &p("zB") + &rr])));
    let pos_h = front([p("xH"), num(0), &p("zH") + &rr]);
    let c_f = front([w.clone(), num(0), &rr - &rf]);
    let axle = mv(&r_h, &[num(0), num(1), num(0)]);
    let az = axle[2].clone();
    let nf = nm.name(
        "nf",
        "sqrt(1 - a_z^2), a the front axle's unit vector: the length of the vertical's projection on the front wheel's plane",
        (num(1) - az.pow(num(2))).expand().pow(num(1) / num(2)),
    );
    // Unit vector from the front wheel centre to its contact point.
    let dvec = [-(&az * &axle[0]) / &nf, -(&az * &axle[1]) / &nf, nf.clone()];
    let height = (&c_f[2] + &rf * &nf).expand();
    let pitch_rules_az = chain(&az, &[("sth", cth.clone()), ("cth", -&sth)]);
    let height_dtheta = (chain(&height, &[("sth", cth.clone()), ("cth", -&sth)])
        + d(&height, "nf") * (-(&az * &pitch_rules_az) / &nf))
        .expand();
    let upright = |e: &Atom| {
        let mut a = e.clone();
        for (s, v) in
            [("sphi", 0), ("cphi", 1), ("sth", 0), ("cth", 1), ("sdel", 0), ("cdel", 1), ("nf", 1)]
        {
            a = subst(&a, s, &num(v));
        }
        // An exact Pythagorean pair for the tilt: the check is then exact rational arithmetic.
        let a = subst(&a, "slam", &(num(3) / num(5)));
        subst(&a, "clam", &(num(4) / num(5))).expand()
    };
    let h0 = upright(&height);
    checks.push(check(
        "reference_contact",
        "the front contact's height vanishes in the reference configuration (lean, pitch, steer zero), here at sin(lambda) = 3/5",
        h0.is_zero(),
        format!("height there: {h0}"),
    ));
    nm.put(
        "contact_height",
        "z coordinate (down positive) of the front wheel's lowest point relative to the ground: the holonomic constraint h(phi, theta, delta) = 0 fixes the pitch (m)",
        height.clone(),
    );
    nm.put(
        "contact_height_dtheta",
        "partial derivative of contact_height with respect to the pitch theta, for Newton's method (m)",
        height_dtheta,
    );

    // Rates and the time derivative at fixed rates.
    let u = |k: usize| var(SPEEDS[k]);
    let (phid, deltad, thetard, thetad, psid, thetafd) = (u(0), u(1), u(2), u(3), u(4), u(5));
    let rules: Vec<(&str, Atom)> = vec![
        ("sphi", &cphi * &phid),
        ("cphi", -(&sphi * &phid)),
        ("sth", &cth * &thetad),
        ("cth", -(&sth * &thetad)),
        ("sdel", &cdel * &deltad),
        ("cdel", -(&sdel * &deltad)),
    ];
    // The steer rotation's entries: d/dt rS_ij = (d r_s_ij / d delta) deltad.
    let steer_rules = [("sdel", &cdel * &deltad), ("cdel", -(&sdel * &deltad))];
    let mut rules = rules;
    for k in 0..9 {
        let rate = chain(&r_s[k / 3][k % 3], &steer_rules);
        if !rate.is_zero() {
            rules.push((RS[k / 3][k % 3], rate));
        }
    }
    // The time derivative at constant speeds of an expression in the sines and cosines. n_F is
    // not among the leaves: nothing differentiated this way contains it (the contact direction's
    // derivative is built by hand below).
    let nf_symbol = nf.get_symbol().expect("nf is a symbol");
    let dtf = |e: &Atom| {
        assert!(!e.contains_symbol(nf_symbol), "dtf of an expression with nf: {e}");
        chain(e, &rules)
    };
    let dtf3 = |v: &V3| map3(v, dtf);
    let zhat = [num(0), num(0), num(1)];
    let yaw_cross = |v: &V3| [-(&psid * &v[1]), &psid * &v[0], num(0)];
    let v_p = [-(&rr * (&thetad + &thetard)), num(0), num(0)];
    let velocity = |r: &V3| expand3(&add(&add(&v_p, &dtf3(r)), &yaw_cross(r)));

    // Angular velocities: rear frame in yawed-frame components (for the contact) and in body
    // components.
    let s_axis = [slam.clone(), num(0), clam.clone()];
    let w_b_yaw = [phid.clone(), &thetad * &cphi, &psid + &thetad * &sphi];
    let w_f_yaw =
        expand3(&add(&add(&w_b_yaw, &scale(&deltad, &mv(&r_b, &s_axis))), &scale(&thetafd, &axle)));
    let w_b_body = expand3(&add(
        &mv(&transpose(&rot_y(&sth, &cth)), &[phid.clone(), &sphi * &psid, &cphi * &psid]),
        &[num(0), thetad.clone(), num(0)],
    ));
    let w_r_body = expand3(&add(&w_b_body, &[num(0), thetard.clone(), num(0)]));
    let w_h_body = expand3(&add(&mv(&transpose(&rs_sym), &w_b_body), &scale(&deltad, &s_axis)));
    let w_f_body = expand3(&add(&w_h_body, &[num(0), thetafd.clone(), num(0)]));

    // The emitted velocities and accelerations follow the rigid-body chain (yawed-frame
    // components): for points X, Y fixed in a frame of angular velocity w and inertial angular
    // acceleration alpha, v_X = v_Y + w x rho and a_X = a_Y + alpha x rho + w x (w x rho),
    // rho = X - Y, from the rear contact P (a_P = Omega x v_P, Omega = psid z the yawed
    // frame's rate) through the rear wheel centre (lean frame), the steering axis point A and
    // the mass centres (rear and front frames), with the position vectors rho named. Written
    // out and expanded instead, the velocities and their time derivatives took about 2,400
    // operations more.
    // Everything is at constant speeds (the dependent accelerations' velocity parts).
    // Named quantities and their expressions, in the order they are named (later ones may
    // name earlier ones): the checks substitute them back, latest first.
    let mut unname: Vec<(String, Atom)> =
        (0..9).map(|k| (RS[k / 3][k % 3].to_string(), r_s[k / 3][k % 3].clone())).collect();
    let mut name_vec = |nm: &mut Named, name: &str, description: &str, v: &V3| -> V3 {
        let named = nm.name3(name, description, v);
        for (k, c) in ["x", "y", "z"].iter().enumerate() {
            unname.push((format!("{name}_{c}"), v[k].clone()));
        }
        named
    };
    let omega_yaw = [num(0), num(0), psid.clone()];
    let w_l = [phid.clone(), num(0), psid.clone()];
    let alpha_l = cross(&omega_yaw, &w_l);
    let alpha_b = add(&dtf3(&w_b_yaw), &cross(&omega_yaw, &w_b_yaw));
    let s_h = name_vec(
        &mut nm,
        "sH",
        "the steering axis' unit vector (yawed frame)",
        &expand3(&mv(&r_b, &s_axis)),
    );
    let w_h_yaw = add(&w_b_yaw, &scale(&deltad, &s_h));
    let alpha_h = add(&alpha_b, &scale(&deltad, &cross(&w_b_yaw, &s_h)));
    let rho_b = name_vec(
        &mut nm,
        "rhoB",
        "from the rear wheel centre to B's mass centre (yawed frame, m)",
        &expand3(&mv(&r_b, &[p("xB"), num(0), &p("zB") + &rr])),
    );
    let rho_a = name_vec(
        &mut nm,
        "rhoA",
        "from the rear wheel centre to the steering axis point A, the front frame's reference point (yawed frame, m)",
        &expand3(&mv(&r_b, &a0)),
    );
    // From A to a point of the front frame: R_B (R_S (x - A)), the vector in the rear frame
    // named first.
    let q_h = name_vec(
        &mut nm,
        "qH",
        "from A to H's mass centre in the rear frame's axes (m)",
        &expand3(&mv(&rs_sym, &sub(&[p("xH"), num(0), &p("zH") + &rr], &a0))),
    );
    let rho_h = name_vec(
        &mut nm,
        "rhoH",
        "from A to H's mass centre (yawed frame, m)",
        &expand3(&mv(&r_b, &q_h)),
    );
    let q_f = name_vec(
        &mut nm,
        "qF",
        "from A to the front wheel centre C_F in the rear frame's axes (m)",
        &expand3(&mv(&rs_sym, &sub(&[w.clone(), num(0), &rr - &rf], &a0))),
    );
    let rho_f = name_vec(
        &mut nm,
        "rhoF",
        "from A to the front wheel centre C_F (yawed frame, m)",
        &expand3(&mv(&r_b, &q_f)),
    );
    let step = |y: &(V3, V3), w: &V3, alpha: &V3, rho: &V3| -> (V3, V3) {
        let wr = cross(w, rho);
        (add(&y.0, &wr), add(&add(&y.1, &cross(alpha, rho)), &cross(w, &wr)))
    };
    let kin_p = (v_p.clone(), cross(&omega_yaw, &v_p));
    let kin_r = step(&kin_p, &w_l, &alpha_l, &c_r);
    let kin_b = step(&kin_r, &w_b_yaw, &alpha_b, &rho_b);
    let kin_a = step(&kin_r, &w_b_yaw, &alpha_b, &rho_a);
    let kin_h = step(&kin_a, &w_h_yaw, &alpha_h, &rho_h);
    let kin_f = step(&kin_a, &w_h_yaw, &alpha_h, &rho_f);
    // The chain's vectors equal the direct ones only with sin^2 + cos^2 = 1 (R R^T = 1 makes
    // R [w]x R^T = [R w]x): the comparisons are made, exactly, at two points with rational
    // sines and cosines (Pythagorean triples), every parameter and speed kept symbolic.
    // (angle, numerators of its sine and cosine, their denominator)
    let trig_points: [[(&str, i64, i64, i64); 4]; 2] = [
        [("phi", 3, 4, 5), ("th", 5, 12, 13), ("del", 8, 15, 17), ("lam", 7, 24, 25)],
        [("phi", -20, 21, 29), ("th", 12, 35, 37), ("del", -9, 40, 41), ("lam", 11, 60, 61)],
    ];
    let same = |a: &Atom, b: &Atom, table: &[(String, Atom)]| {
        let mut x = a - b;
        for (n, v) in table.iter().rev() {
            x = subst(&x, n, v);
        }
        trig_points.iter().all(|point| {
            let mut y = x.clone();
            for &(angle, sin_num, cos_num, den) in point {
                assert_eq!(
                    sin_num * sin_num + cos_num * cos_num,
                    den * den,
                    "{angle}: on the circle"
                );
                y = subst(&y, &format!("s{angle}"), &(num(sin_num) / num(den)));
                y = subst(&y, &format!("c{angle}"), &(num(cos_num) / num(den)));
            }
            y.expand().is_zero()
        })
    };
    let mut chain_detail = Vec::new();
    for (label, kin, pos) in
        [("R", &kin_r, &c_r), ("B", &kin_b, &pos_b), ("H", &kin_h, &pos_h), ("F", &kin_f, &c_f)]
    {
        let direct = velocity(pos);
        let vel_ok = (0..3).all(|k| same(&kin.0[k], &direct[k], &unname));
        let acc = add(&dtf3(&direct), &yaw_cross(&direct));
        let acc_ok = (0..3).all(|k| same(&kin.1[k], &acc[k], &unname));
        chain_detail.push(format!("{label}: velocity {vel_ok}, acceleration {acc_ok}"));
    }
    checks.push(check(
        "rigid_chain",
        "the rigid-body chain's velocities and constant-speed accelerations of the four mass centres equal the time derivatives of their positions (d/dt of the components plus Omega x, Omega = psid z)",
        chain_detail.iter().all(|t| !t.contains("false")),
        chain_detail.join("; "),
    ));

    // Front contact: the material point's velocity and the three constraint rows.
    let v_cf = velocity(&c_f);
    let v_contact = expand3(&add(&v_cf, &cross(&w_f_yaw, &scale(&rf, &dvec))));
    let dirs = [
        zhat.clone(),
        [axle[0].clone(), axle[1].clone(), num(0)],
        [axle[1].clone(), -&axle[0], num(0)],
    ];
    let rows: Vec<Atom> = dirs.iter().map(|e| dot(e, &v_contact).expand()).collect();
    // Coefficients of the rows in the six speeds.
    let coef: Vec<Vec<Atom>> =
        rows.iter().map(|r| SPEEDS.iter().map(|s| d(r, s).expand()).collect()).collect();
    let mut rebuilt_ok = true;
    for (k, r) in rows.iter().enumerate() {
        let mut rebuilt = num(0);
        for j in 0..6 {
            rebuilt += &coef[k][j] * u(j);
        }
        rebuilt_ok &= (r - rebuilt).expand().is_zero();
    }
    checks.push(check(
        "rows_linear",
        "each front-contact constraint row is linear and homogeneous in the six speeds",
        rebuilt_ok,
        "row minus the sum of its speed coefficients times the speeds expands to 0".to_string(),
    ));
    // Triangular structure: row 1 free of psid, thetaFd, thetaRd; row 2 free of thetaFd.
    let zeros = [(0, 2), (0, 4), (0, 5), (1, 5)];
    let tri = zeros.iter().all(|&(k, j)| coef[k][j].is_zero());
    checks.push(check(
        "rows_triangular",
        "the vertical row has no yaw-rate, rear-wheel-rate or front-wheel-rate term and the row along the axle's horizontal projection no front-wheel-rate term, so the rows give the pitch rate, the yaw rate and the front wheel rate one after another",
        tri,
        format!(
            "coefficients: {}",
            zeros.iter().map(|&(k, j)| format!("row {} {}: {}", k + 1, SPEEDS[j], coef[k][j])).collect::<Vec<_>>().join("; ")
        ),
    ));
    let axle_sym = [0, 1, 2].map(|k| {
        let n = ["ax", "ay", "az"][k];
        nm.name(
            n,
            &format!("{n}, a component of the front axle's unit vector (yawed frame)"),
            axle[k].clone(),
        )
    });
    let [ax, ay, az_s] = &axle_sym;
    // The rows' coefficients are handed over factored too: row k's coefficient of speed j is
    // e_k . (dv_{C_F}/du_j + dw_F/du_j x r_F d), with the axle's components named and
    // d = (-a_z a_x/n_F, -a_z a_y/n_F, n_F).
    let e = [zhat.clone(), [ax.clone(), ay.clone(), num(0)], [ay.clone(), -ax, num(0)]];
    let d_sym = [-(az_s * ax) / &nf, -(az_s * ay) / &nf, nf.clone()];
    let w_f_axle = add(&w_h_yaw, &scale(&thetafd, &axle_sym));
    unname.extend(["ax", "ay", "az"].iter().zip(&axle).map(|(n, a)| (n.to_string(), a.clone())));
    let mut factored = vec![vec![num(0); 6]; 3];
    for j in 0..6 {
        let dv = map3(&kin_f.0, |c| d(c, SPEEDS[j]).expand());
        let dw = map3(&w_f_axle, |c| d(c, SPEEDS[j]).expand());
        let part = add(&dv, &cross(&dw, &scale(&rf, &d_sym)));
        for k in 0..3 {
            factored[k][j] = dot(&e[k], &part);
        }
    }
    let factored_ok = (0..3).all(|k| (0..6).all(|j| same(&factored[k][j], &coef[k][j], &unname)));
    checks.push(check(
        "rows_factored",
        "the factored row coefficients e_k . (dv_CF/du_j + dw_F/du_j x r_F d) equal the coefficients of the expanded rows",
        factored_ok,
        "with the named vectors written out, each difference vanishes at the two rational points of the rigid_chain check".to_string(),
    ));
    let mut bn = vec![vec![num(0); 6]; 3];
    for k in 0..3 {
        for j in 0..6 {
            if !coef[k][j].is_zero() {
                bn[k][j] = nm.name(
                    &format!("b{}_{}", k + 1, SPEEDS[j]),
                    &format!(
                        "coefficient of {} in front-contact constraint row {} (velocity of the wheel's contact point along {})",
                        SPEEDS[j],
                        k + 1,
                        ["the vertical", "(a_x, a_y, 0)", "(a_y, -a_x, 0)"][k]
                    ),
                    factored[k][j].clone(),
                );
            }
        }
    }
    // Dependent speeds as linear forms in the independent ones: A[d][i].
    let mut a = vec![vec![num(0); 3]; 3];
    for i in 0..3 {
        let th = -(&bn[0][i]) / &bn[0][3];
        a[0][i] = nm.name(
            &format!("a_thetad_{}", INDEPENDENT[i]),
            &format!("d thetad / d {}: pitch rate per unit {}", INDEPENDENT[i], INDEPENDENT[i]),
            th,
        );
        let ps = -(&bn[1][i] + &bn[1][3] * &a[0][i]) / &bn[1][4];
        a[1][i] = nm.name(
            &format!("a_psid_{}", INDEPENDENT[i]),
            &format!("d psid / d {}: yaw rate per unit {}", INDEPENDENT[i], INDEPENDENT[i]),
            ps,
        );
        let tf = -(&bn[2][i] + &bn[2][3] * &a[0][i] + &bn[2][4] * &a[1][i]) / &bn[2][5];
        a[2][i] = nm.name(
            &format!("a_thetaFd_{}", INDEPENDENT[i]),
            &format!(
                "d thetaFd / d {}: front wheel rate per unit {}",
                INDEPENDENT[i], INDEPENDENT[i]
            ),
            tf,
        );
    }
    for dd in 0..3 {
        let mut e = num(0);
        for i in 0..3 {
            e += &a[dd][i] * u(i);
        }
        nm.put(
            DEPENDENT[dd],
            &format!(
                "{} from the front wheel's rolling (rad/s)",
                ["pitch rate", "yaw rate", "front wheel rate relative to the front frame"][dd]
            ),
            e,
        );
    }
    nm.put(
        "rear_speed",
        "speed of the rear contact point along the heading, -rR (thetad + thetaRd) (m/s)",
        -(&rr * (&thetad + &thetard)),
    );
    // Velocity parts of the dependent accelerations: the time derivatives of the rows at
    // constant speeds. Row k is e_k . v_c, v_c = v_{C_F} + w_F x (r_F d) the contact point's
    // material velocity, so its derivative is e_k' . v_c + e_k . v_c'; the first term vanishes
    // wherever the rows do (v_c = 0 when the dependent speeds satisfy the constraints, as they
    // do at run time), and the second is built from named factors instead of differentiating
    // the expanded rows (that took 24,292 of the model's 30,554 operations).
    let axle_dot = [0, 1, 2].map(|k| {
        let n = ["axd", "ayd", "azd"][k];
        nm.name(
            n,
            &format!("time derivative of {} at constant speeds (1/s)", &n[..2]),
            dtf(&axle[k]),
        )
    });
    let [axd, ayd, azd] = &axle_dot;
    let nfd = nm.name(
        "nfd",
        "time derivative of nf at constant speeds, -a_z a_z'/nf (1/s)",
        -(az_s * azd) / &nf,
    );
    // The derivative of d.
    let d_dot = [
        -(azd * ax + az_s * axd) / &nf + az_s * ax * &nfd / nf.pow(num(2)),
        -(azd * ay + az_s * ayd) / &nf + az_s * ay * &nfd / nf.pow(num(2)),
        nfd.clone(),
    ];
    // Component derivatives in the yawed frame: the inertial ones less Omega x (the vector).
    let wf = nm.name3("wF_yaw", "angular velocity of F (yawed frame, rad/s)", &w_f_axle);
    let alpha_f = add(&alpha_h, &scale(&thetafd, &cross(&w_h_yaw, &axle_sym)));
    let wf_dot = nm.name3(
        "wF_yaw_dot",
        "time derivative of wF_yaw's components at constant speeds (rad/s^2)",
        &sub(&alpha_f, &yaw_cross(&wf)),
    );
    let vcf =
        nm.name3("vcF", "velocity of the front wheel centre C_F (yawed frame, m/s)", &kin_f.0);
    let vcf_dot = nm.name3(
        "vcF_dot",
        "time derivative of the components of C_F's velocity (yawed frame) at constant speeds (m/s^2)",
        &sub(&kin_f.1, &yaw_cross(&vcf)),
    );
    let vc_dot =
        add(&vcf_dot, &add(&cross(&wf_dot, &scale(&rf, &d_sym)), &cross(&wf, &scale(&rf, &d_dot))));
    let dc: Vec<Atom> = e.iter().map(|ek| dot(ek, &vc_dot)).collect();
    let dcn: Vec<Atom> = (0..3)
        .map(|k| {
            nm.name(
                &format!("dc{}", k + 1),
                &format!(
                    "time derivative of constraint row {} at constant speeds (quadratic in the speeds)",
                    k + 1
                ),
                dc[k].clone(),
            )
        })
        .collect();
    let thdd0 = nm.name(
        "thetadd0",
        "pitch acceleration when the independent accelerations vanish (rad/s^2)",
        -(&dcn[0]) / &bn[0][3],
    );
    let psdd0 = nm.name(
        "psidd0",
        "yaw acceleration when the independent accelerations vanish (rad/s^2)",
        -(&dcn[1] + &bn[1][3] * &thdd0) / &bn[1][4],
    );
    let tfdd0 = nm.name(
        "thetaFdd0",
        "front wheel acceleration when the independent accelerations vanish (rad/s^2)",
        -(&dcn[2] + &bn[2][3] * &thdd0 + &bn[2][4] * &psdd0) / &bn[2][5],
    );
    let dep0 = [thdd0, psdd0, tfdd0];

    // Bodies.
    let bodies = [
        Body {
            name: "R",
            mass: p("mR"),
            velocity: kin_r.0.clone(),
            omega: w_r_body,
            inertia: inertia("IRxx", "IRyy", "IRxx", None),
            position: c_r.clone(),
        },
        Body {
            name: "B",
            mass: p("mB"),
            velocity: kin_b.0.clone(),
            omega: w_b_body.clone(),
            inertia: inertia("IBxx", "IByy", "IBzz", Some("IBxz")),
            position: pos_b.clone(),
        },
        Body {
            name: "H",
            mass: p("mH"),
            velocity: kin_h.0.clone(),
            omega: w_h_body.clone(),
            inertia: inertia("IHxx", "IHyy", "IHzz", Some("IHxz")),
            position: pos_h.clone(),
        },
        Body {
            name: "F",
            mass: p("mF"),
            velocity: kin_f.0.clone(),
            omega: w_f_body,
            inertia: inertia("IFxx", "IFyy", "IFxx", None),
            position: c_f.clone(),
        },
    ];
    let g = p("g");
    // Energy: every body's velocity and angular velocity.
    let mut kinetic = num(0);
    let mut potential = num(0);
    let mut om_of = Vec::new();
    for b in &bodies {
        let vel = nm.name3(
            &format!("v_{}", b.name),
            &format!("velocity of {}'s mass centre (yawed frame, m/s)", b.name),
            &b.velocity,
        );
        let om = nm.name3(
            &format!("w_{}", b.name),
            &format!("angular velocity of {} (body frame, rad/s)", b.name),
            &b.omega,
        );
        let iw = mv(&b.inertia, &om);
        kinetic = kinetic + &b.mass * dot(&vel, &vel) / num(2) + dot(&om, &iw) / num(2);
        potential -= &b.mass * &g * &b.position[2];
        om_of.push(om);
    }
    // Non-holonomic partial velocities.
    let partial = |x: &V3, i: usize| -> V3 {
        let mut out = map3(x, |c| d(c, INDEPENDENT[i]));
        for dd in 0..3 {
            out = add(&out, &scale(&a[dd][i], &map3(x, |c| d(c, DEPENDENT[dd]))));
        }
        out
    };
    // The translational partial velocities and constant-speed acceleration of a point.
    let point = |nm: &mut Named, name: &str, what: &str, kin: &(V3, V3)| -> (Vec<V3>, V3) {
        let vt: Vec<V3> = (0..3)
            .map(|i| {
                nm.name3(
                    &format!("vt_{name}_{}", INDEPENDENT[i]),
                    &format!(
                        "partial velocity of {what} for {} (yawed frame, m per unit speed)",
                        INDEPENDENT[i]
                    ),
                    &partial(&kin.0, i),
                )
            })
            .collect();
        let mut acc0 = kin.1.clone();
        for dd in 0..3 {
            acc0 = add(&acc0, &scale(&dep0[dd], &map3(&kin.0, |c| d(c, DEPENDENT[dd]))));
        }
        let acc0 = nm.name3(
            &format!("acc0_{name}"),
            &format!(
                "acceleration of {what} when the independent accelerations vanish (yawed frame, m/s^2)"
            ),
            &acc0,
        );
        (vt, acc0)
    };
    // The rear wheel centre's, for the runtime's accelerations.
    let _ = point(&mut nm, "R", "the rear wheel centre", &kin_r);
    // The dynamics by assemblies: each frame with its wheel, whose centre is fixed in it, as one
    // body of the total mass at the assembly's mass centre T, with the inertia about T of the
    // frame, the wheel (diag(I_xx, I_yy, I_xx) in the frame's axes, by symmetry) and the two
    // masses' offsets d_k from T (sum of m_k (|d_k|^2 1 - d_k d_k^T), in the frame's axes).
    // Kane's sums over the two bodies equal the assembly's (sum m_k d_k = 0), which halves the
    // terms of M3 and f3; the wheel's spin adds the terms written out below.
    let parallel = |parts: &[(Atom, V3)]| -> [Atom; 4] {
        let mut j = [num(0), num(0), num(0), num(0)];
        for (m, dk) in parts {
            j[0] = &j[0] + m * dk[2].pow(num(2));
            j[1] = &j[1] + m * (dk[0].pow(num(2)) + dk[2].pow(num(2)));
            j[2] = &j[2] + m * dk[0].pow(num(2));
            j[3] = &j[3] - m * &dk[0] * &dk[2];
        }
        j
    };
    let (m_r, m_b, m_h, m_f) = (p("mR"), p("mB"), p("mH"), p("mF"));
    let mass_rear = &m_r + &m_b;
    let mass_front = &m_h + &m_f;
    // Offsets in the frames' axes: B's mass centre from the rear wheel centre; H's mass centre
    // and the front wheel centre from A.
    let off_b = [p("xB"), num(0), &p("zB") + &rr];
    let off_h = sub(&[p("xH"), num(0), &p("zH") + &rr], &a0);
    let off_f = sub(&[w.clone(), num(0), &rr - &rf], &a0);
    // The assemblies' mass centres (the y components vanish), named.
    let mut centre = |name: &str, what: &str, v: V3| -> V3 {
        let x = nm.name(&format!("{name}_x"), &format!("{what}, x component (m)"), v[0].clone());
        let z = nm.name(&format!("{name}_z"), &format!("{what}, z component (m)"), v[2].clone());
        [x, num(0), z]
    };
    let e_rear = centre(
        "eTR",
        "the rear assembly's mass centre from the rear wheel centre in the rear frame's axes",
        scale(&(&m_b / &mass_rear), &off_b),
    );
    let e_front = centre(
        "eTF",
        "the front assembly's mass centre from A in the front frame's axes",
        scale(&(num(1) / &mass_front), &add(&scale(&m_h, &off_h), &scale(&m_f, &off_f))),
    );
    let j_rear =
        parallel(&[(m_r.clone(), scale(&num(-1), &e_rear)), (m_b.clone(), sub(&off_b, &e_rear))]);
    let j_front =
        parallel(&[(m_h.clone(), sub(&off_h, &e_front)), (m_f.clone(), sub(&off_f, &e_front))]);
    let assembly_inertia = |nm: &mut Named,
                            name: &str,
                            frame: &M3,
                            wheel: &M3,
                            j: [Atom; 4]|
     -> M3 {
        let comps = ["xx", "yy", "zz", "xz"];
        let at = [(0, 0), (1, 1), (2, 2), (0, 2)];
        let named: Vec<Atom> = (0..4)
            .map(|k| {
                let (r, c) = at[k];
                nm.name(
                    &format!("I{name}_{}", comps[k]),
                    &format!(
                        "{} entry of the {} assembly's inertia about its mass centre (frame axes, kg m^2)",
                        comps[k],
                        if name == "TR" { "rear" } else { "front" }
                    ),
                    &frame[r][c] + &wheel[r][c] + &j[k],
                )
            })
            .collect();
        [
            [named[0].clone(), num(0), named[3].clone()],
            [num(0), named[1].clone(), num(0)],
            [named[3].clone(), num(0), named[2].clone()],
        ]
    };
    let i_rear = assembly_inertia(&mut nm, "TR", &bodies[1].inertia, &bodies[0].inertia, j_rear);
    let i_front = assembly_inertia(&mut nm, "TF", &bodies[2].inertia, &bodies[3].inertia, j_front);
    let rho_tr = nm.name3(
        "rhoTR",
        "from the rear wheel centre to the rear assembly's mass centre (yawed frame, m)",
        &expand3(&mv(&r_b, &e_rear)),
    );
    let q_tf = nm.name3(
        "qTF",
        "from A to the front assembly's mass centre in the rear frame's axes (m)",
        &expand3(&mv(&rs_sym, &e_front)),
    );
    let rho_tf = nm.name3(
        "rhoTF",
        "from A to the front assembly's mass centre (yawed frame, m)",
        &expand3(&mv(&r_b, &q_tf)),
    );
    let kin_tr = step(&kin_r, &w_b_yaw, &alpha_b, &rho_tr);
    let kin_tf = step(&kin_a, &w_h_yaw, &alpha_h, &rho_tf);
    let mut m3 = vec![vec![num(0); 3]; 3];
    let mut f3 = [num(0), num(0), num(0)];
    let yhat = [num(0), num(1), num(0)];
    let assemblies = [
        ("TR", "the rear assembly's mass centre", mass_rear, &kin_tr, 1, i_rear, 0),
        ("TF", "the front assembly's mass centre", mass_front, &kin_tf, 2, i_front, 3),
    ];
    for (name, what, mass, kin, frame, inertia, wheel) in assemblies {
        let (vt, acc0) = point(&mut nm, name, what, kin);
        let force = sub(&scale(&g, &zhat), &acc0);
        for i in 0..3 {
            for j in i..3 {
                m3[i][j] = &m3[i][j] + &mass * dot(&vt[i], &vt[j]);
            }
            f3[i] = &f3[i] + &mass * dot(&force, &vt[i]);
        }
        // Rotation. The wheel turns with its frame C plus its spin about the axle y:
        // omega_W = omega_C + spin y, so its partial angular velocities are C's plus s_i y (s_i:
        // the spin's partial rate) and its angular acceleration at zero independent
        // accelerations alpha0_C + sigma y (sigma: the spin's acceleration then). Its spin's
        // terms: wt_W,i . I_W wt_W,j = wt_C,i . I_W wt_C,j + I_yy (s_i wt_C,j,y + s_j wt_C,i,y
        // + s_i s_j); its Euler torque I_W alpha_W + omega_C x I_W omega_W has the y component
        // I_yy (alpha0_C,y + sigma) (I_W is symmetric about y).
        let b = &bodies[frame];
        let (s, spin, sigma): ([Atom; 3], Atom, Atom) = if wheel == 0 {
            ([num(0), num(0), num(1)], thetard.clone(), num(0))
        } else {
            ([0, 1, 2].map(|i| a[2][i].clone()), thetafd.clone(), dep0[2].clone())
        };
        let om = &om_of[frame];
        let wt: Vec<V3> = (0..3)
            .map(|i| {
                nm.name3(
                    &format!("wt_{}_{}", b.name, INDEPENDENT[i]),
                    &format!(
                        "partial angular velocity of {} for {} (body frame)",
                        b.name, INDEPENDENT[i]
                    ),
                    &partial(&b.omega, i),
                )
            })
            .collect();
        let mut alpha0 = dtf3(&b.omega);
        for dd in 0..3 {
            alpha0 = add(&alpha0, &scale(&dep0[dd], &map3(&b.omega, |c| d(c, DEPENDENT[dd]))));
        }
        let alpha0 = nm.name3(
            &format!("alpha0_{}", b.name),
            &format!(
                "time derivative of the components of {}'s angular velocity (in the frame of w_) when the independent accelerations vanish (rad/s^2)",
                b.name
            ),
            &alpha0,
        );
        let iyy = bodies[wheel].inertia[1][1].clone();
        // Euler: dH/dt = I (d omega/dt in the frame's components) + omega x I omega.
        let torque = add(
            &add(&mv(&inertia, &alpha0), &cross(om, &mv(&inertia, om))),
            &add(&scale(&(&sigma * &iyy), &yhat), &cross(om, &scale(&(&spin * &iyy), &yhat))),
        );
        let torque_y = &iyy * (&alpha0[1] + &sigma);
        for i in 0..3 {
            for j in i..3 {
                m3[i][j] = &m3[i][j]
                    + dot(&wt[i], &mv(&inertia, &wt[j]))
                    + &iyy * (&s[i] * &wt[j][1] + &s[j] * &wt[i][1] + &s[i] * &s[j]);
            }
            f3[i] = &f3[i] - dot(&torque, &wt[i]) - &s[i] * &torque_y;
        }
    }
    let labels = ["lean", "steer", "rear wheel"];
    for i in 0..3 {
        for j in i..3 {
            nm.put(
                &format!("m3_{}{}", i + 1, j + 1),
                &format!(
                    "entry ({}, {}) of the mass matrix of the equations for the independent speeds (phid, deltad, thetaRd), rows {} and {}",
                    i + 1,
                    j + 1,
                    labels[i],
                    labels[j]
                ),
                m3[i][j].clone(),
            );
        }
    }
    for i in 0..3 {
        nm.put(
            &format!("f3_{}", i + 1),
            &format!(
                "forcing of the {} equation: M3 (phidd, deltadd, thetaRdd) = f3 (gravity, velocity terms)",
                labels[i]
            ),
            f3[i].clone(),
        );
    }
    nm.put("energy", "total energy: kinetic energy of the four bodies plus gravity's potential, zero at ground level (J)", kinetic + potential);
    let contact = add(&c_f, &scale(&rf, &dvec));
    nm.put(
        "front_contact_x",
        "front contact point relative to the rear contact, along the heading (yawed frame, m)",
        contact[0].clone(),
    );
    nm.put(
        "front_contact_y",
        "front contact point relative to the rear contact, to the right of the heading (yawed frame, m)",
        contact[1].clone(),
    );
    ensure!(
        checks.iter().all(|c| c.holds),
        "whipple_nonlinear checks failed: {:?}",
        checks
            .iter()
            .filter(|c| !c.holds)
            .map(|c| format!("{}: {}", c.id, c.detail))
            .collect::<Vec<_>>()
    );
    Ok(Derivation {
        model: "whipple_nonlinear".to_string(),
        source: file!().to_string(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: INPUTS.iter().map(|s| s.to_string()).collect(),
        formulas: nm.formulas,
        checks,
        nominal: crate::derive::nominal::values("whipple_nonlinear"),
    })
}
