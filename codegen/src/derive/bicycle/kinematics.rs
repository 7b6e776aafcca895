//! Kinematics and rest equilibrium of the bicycle (memoir Part II, ch. II, n° 59–69), derived
//! with symbolica on top of the geometry of n° 43–58 ([`crate::derive::bicycle::geometry`]).
//!
//! The bicycle has three degrees of freedom (n° 59): the lean θ, the steer γ and the rolling σ
//! of the rear wheel. The frame's turning ν about OK, its pitch η about Sj (η is the σ of
//! ch. I, n° 58 bis; its stand-ins are those of σ here) and the front wheel's rolling σ1 follow
//! from the condition that the front wheel's contact point M has no velocity (n° 60). The
//! memoir writes it twice:
//!
//! * n° 61, the analytic method: $\delta M = IR\,\delta\sigma + \delta(M - O)$ with the vectors
//!   of n° 46–47 varied through $\delta I = J\,\delta\nu$, $\delta J = -I\,\delta\nu$, formulas
//!   (3) and (4), and the condensed relation (δη);
//! * n° 62–65, the geometric method: six partial displacements of M projected on K, on the
//!   horizontal normal $N_1$ and on the front tangent $I_1$, giving (δη), (δν), (δσ1).
//!
//! The geometric method is written here with free symbols x, y (the coordinates of M), α, β
//! (n° 57); its tables are compared with the print, and each partial displacement is
//! identified with the analytic one *on the contact*: μ at the lowest point
//! ($\sin\mu = K|H_1 / W_b$, $\cos\mu = K|G / W_b$, $W_b = \cos\beta$) and the letter a
//! eliminated by the height equation (1) of n° 48. The relations (I), (2) of n° 66, the front
//! wheel's rates of n° 66 bis, the fixation paradox of n° 68 and the second derivatives of the
//! rest equilibrium of n° 69 follow, every step a [`Check`].
//!
//! The emitted formulas are the 18 coefficients of the analytic $\delta M$ (the runtime solves
//! them for δη, δν, δσ1 independently of the memoir's relations), the relations (I) and (2) of
//! n° 66 with x, y, α, β replaced by their geometric values, and $\eta''$ along the contact at
//! fixed steer (n° 69), as derived and as printed.

use anyhow::Result;
use symbolica::atom::{Atom, AtomCore};

use crate::cas::{cos_t, sin_t, var};
use crate::cas::{det3, solve_linear};
use crate::derive::bicycle::geometry::{
    self as geo, check, d_angle, formula, h, h1, ijk, ijk_small, is_zero_mod, normal_components,
    om_ab, sc, show, sq, subst, w50, wb, with_ab, zero_theta,
};
use crate::mechanics::frame::{Trihedron, Vector};
use crate::{Check, Derivation, Formula};

/// The six virtual displacements of n° 60, as the symbols of the derivation, with their
/// variables: the rear rolling σ, the lean θ, the turning ν, the pitch η, the steer γ and the
/// front rolling σ1.
const DELTAS: [(&str, &str); 6] = [
    ("dsig", "sigma"),
    ("dth", "theta"),
    ("dnu", "nu"),
    ("deta", "eta"),
    ("dgam", "gamma"),
    ("dsig1", "sigma1"),
];

fn delta(k: usize) -> Atom {
    var(DELTAS[k].0)
}

/// Reads a printed formula of ch. II: η is the σ of ch. I (n° 58 bis); the rest as
/// [`geo::from_printed`].
fn pr(text: &str) -> Atom {
    let t = text
        .replace("sin(eta)", "sin(sigma)")
        .replace("cos(eta)", "cos(sigma)")
        .replace("tan(eta)", "tan(sigma)")
        .replace("sin(theta1)", "(-sin(beta))")
        .replace("cos(theta1)", "cos(beta)");
    geo::from_printed(&t)
}

fn vpr(c: [&str; 3]) -> Vector {
    Vector::new(Trihedron::IJK, pr(c[0]), pr(c[1]), pr(c[2]))
}

fn ijk_of(v: &Vector) -> Vector {
    v.to(Trihedron::IJK).map(|e| e.expand())
}

/// Partial variation of the vector `v` (on I, J, K) with respect to the displacement `q` of
/// [`DELTAS`]: the derivative of its components, and for ν the turning of I, J
/// ($\delta I = J\,\delta\nu$, $\delta J = -I\,\delta\nu$, n° 61).
fn variation(v: &Vector, q: &str) -> Vector {
    let v = ijk_of(v);
    match q {
        "nu" => Vector::new(Trihedron::IJK, -&v.comps[1], v.comps[0].clone(), Atom::num(0)),
        "sigma" => Vector::zero(Trihedron::IJK),
        _ => {
            let angle = match q {
                "eta" => "sigma",
                "sigma1" => "mu",
                other => other,
            };
            v.map(|e| d_angle(e, angle).expand())
        }
    }
}

fn vdiff_zero(d: &Vector) -> bool {
    d.comps.iter().all(is_zero_mod)
}

/// A [`Check`] that the vector `diff` vanishes, `derived` its derived side (`diff` =
/// `derived` − expected, in the same trihedron), run again with `derived` perturbed
/// ([`crate::falsify`]) and the expected side kept.
fn vcheck(
    section: &str,
    id: &str,
    statement: &str,
    derived: &Vector,
    diff: &Vector,
    detail: &str,
) -> Check {
    let holds = vdiff_zero(diff);
    let perturbed = crate::falsify::perturb(&derived.comps, |d| {
        (0..3).all(|i| is_zero_mod(&(&diff.comps[i] - &derived.comps[i] + &d[i])))
    });
    let shown: Vec<String> = diff
        .comps
        .iter()
        .map(|c| {
            if is_zero_mod(c) {
                return "0".to_string();
            }
            let s = show(&geo::reduce(&c.expand()));
            if s.len() > 200 {
                format!("{} terms", c.expand().nterms())
            } else {
                s
            }
        })
        .collect();
    Check {
        perturbed: Some(perturbed),
        section: section.into(),
        id: id.into(),
        statement: statement.into(),
        holds,
        detail: format!(
            "{detail}; numerators of the differences on I, J, K, reduced: [{}]",
            shown.join(", ")
        ),
    }
}

fn coeff(e: &Atom, sym: &Atom) -> Atom {
    e.derivative(sym.get_symbol().expect("a symbol")).expand()
}

/// Derives every kinematic and rest-equilibrium formula and runs the checks.
pub fn derive() -> Result<Derivation> {
    let mut checks = Vec::new();
    let r_ = var("R");
    let c_ = var("c");
    let one = Atom::num(1);
    let (s_mu, c_mu) = sc("mu");
    let c_g = sc("gamma").1;
    let (s_e, c_e) = sc("sigma");
    let (s_a, c_a) = sc("alpha");
    let (s_b, c_b) = sc("beta");
    let (s_t, c_t) = (sin_t(), cos_t());
    let k_big = ijk(2);
    let k_small = ijk_small(2);

    // n° 61: delta(M - O) of (3) and the variations (4).
    let om = ijk_of(&om_ab());
    let qs: Vec<&str> = DELTAS.iter().map(|(_, q)| *q).collect();
    let g_vec = geo::g();
    // The variations of a derived OM against the printed (3).
    let check3 = |om: &Vector| {
        let parts: Vec<Vector> = qs.iter().map(|q| variation(om, q)).collect();
        let mut ok3 = true;
        for q in ["theta", "eta", "gamma", "nu"] {
            let rhs = variation(&k_small, q)
                .scale(&r_)
                .add(&variation(&h(), q).scale(&var("a")))
                .add(&variation(&g_vec, q).scale(&-(var("b") + &r_ * &c_mu)))
                .add(&variation(&h1(), q).scale(&(&c_ - &r_ * &s_mu)));
            let k = qs.iter().position(|x| *x == q).expect("a displacement");
            ok3 &= vdiff_zero(&parts[k].sub(&rhs));
        }
        let d_sig1 = g_vec.scale(&(&r_ * &s_mu)).sub(&h1().scale(&(&r_ * &c_mu)));
        ok3 && vdiff_zero(&parts[5].sub(&d_sig1))
    };
    let ok3 = check3(&om);
    let parts: Vec<Vector> = qs.iter().map(|q| variation(&om, q)).collect();
    let perturbed = crate::falsify::perturb(&om.comps, |d| {
        check3(&Vector::new(om.frame, d[0].clone(), d[1].clone(), d[2].clone()))
    });
    checks.push(Check {
        perturbed: Some(crate::Perturbed { what: format!("{} (OM of n° 46, before its variations)", perturbed.what), ..perturbed }),
        section: "61".into(),
        id: "variation_3_61".into(),
        statement: "delta(M - O) is the printed (3): R dk + a dH - (b + R cos mu) dG + (c - R sin mu) dH1 + (G R sin mu - H1 R cos mu) dsigma1, with dI = J dnu, dJ = -I dnu".into(),
        holds: ok3,
        detail: "for each of dtheta, deta, dgamma, dnu and dsigma1 the partial variation of OM (n° 46) minus the printed combination reduces to 0 on I, J, K".into(),
    });
    // The printed (4): per vector, per displacement, the components on I, J, K.
    type Rows<'a> = [(&'a str, [&'a str; 3]); 4];
    let zero = ["0", "0", "0"];
    let dk: Rows = [
        ("theta", ["0", "-cos(theta)", "-sin(theta)"]),
        ("nu", ["sin(theta)", "0", "0"]),
        ("eta", zero),
        ("gamma", zero),
    ];
    let dh_printed: Rows = [
        ("theta", ["0", "-cos(theta)*sin(eta)", "-sin(theta)*sin(eta)"]),
        ("nu", ["sin(theta)*sin(eta)", "cos(eta)", "0"]),
        ("eta", ["-sin(eta) - sin(theta)*cos(eta)", "0", "cos(theta)*cos(eta)"]),
        ("gamma", zero),
    ];
    let dh_read: Rows = [
        dh_printed[0],
        dh_printed[1],
        ("eta", ["-sin(eta)", "-sin(theta)*cos(eta)", "cos(theta)*cos(eta)"]),
        ("gamma", zero),
    ];
    let dg: Rows = [
        ("theta", ["0", "-cos(theta)*cos(eta)", "-sin(theta)*cos(eta)"]),
        ("nu", ["sin(theta)*cos(eta)", "-sin(eta)", "0"]),
        ("eta", ["-cos(eta)", "sin(theta)*sin(eta)", "-cos(theta)*sin(eta)"]),
        ("gamma", zero),
    ];
    let dh1: Rows = [
        (
            "theta",
            [
                "0",
                "-(sin(theta)*sin(gamma) + cos(theta)*cos(gamma)*sin(eta))",
                "cos(theta)*sin(gamma) - sin(theta)*cos(gamma)*sin(eta)",
            ],
        ),
        (
            "nu",
            [
                "-(cos(theta)*sin(gamma) - sin(theta)*cos(gamma)*sin(eta))",
                "cos(eta)*cos(gamma)",
                "0",
            ],
        ),
        (
            "eta",
            [
                "-sin(eta)*cos(gamma)",
                "-sin(theta)*cos(gamma)*cos(eta)",
                "cos(theta)*cos(gamma)*cos(eta)",
            ],
        ),
        (
            "gamma",
            [
                "-cos(eta)*sin(gamma)",
                "cos(theta)*cos(gamma) + sin(theta)*sin(gamma)*sin(eta)",
                "sin(theta)*cos(gamma) - cos(theta)*sin(gamma)*sin(eta)",
            ],
        ),
    ];
    let table4 = |id: &str, name: &str, v: &Vector, rows: &Rows, note: &str| {
        let mut diff = Vector::zero(Trihedron::IJK);
        // The derived side: the variations of n° 47's vector, weighted as `diff`.
        let mut derived = Vector::zero(Trihedron::IJK);
        let mut bad = Vec::new();
        for (q, comps) in rows {
            derived = derived.add(&variation(v, q).scale(&var(&format!("w_{q}"))));
            let d = variation(v, q).sub(&vpr(*comps));
            if !vdiff_zero(&d) {
                bad.push(format!(
                    "d{q}: [{}]",
                    d.comps
                        .iter()
                        .map(|c| show(&geo::reduce(&c.expand())))
                        .collect::<Vec<_>>()
                        .join(", ")
                ));
            }
            diff = diff.add(&d.scale(&var(&format!("w_{q}"))));
        }
        let perturbed = crate::falsify::perturb(&derived.comps, |dd| {
            (0..3).all(|i| is_zero_mod(&(&diff.comps[i] - &derived.comps[i] + &dd[i])))
        });
        Check {
            perturbed: Some(perturbed),
            section: "61".into(),
            id: id.into(),
            statement: format!(
                "the variation d{name} (n° 47 varied) is the printed line of (4){note}"
            ),
            holds: vdiff_zero(&diff),
            detail: if bad.is_empty() {
                "the coefficients of dtheta, dnu, deta, dgamma on I, J, K all agree".into()
            } else {
                format!("differing coefficients (derived - printed): {}", bad.join("; "))
            },
        }
    };
    checks.push(table4("variation_k_61", "k", &k_small, &dk, ""));
    checks.push(table4(
        "variation_h_61_as_printed",
        "H",
        &h(),
        &dh_printed,
        " as printed: (-I sin eta - I sin theta cos eta + K cos theta cos eta) deta",
    ));
    checks.push(table4(
        "variation_h_61",
        "H",
        &h(),
        &dh_read,
        " read with J for the second I: (-I sin eta - J sin theta cos eta + K cos theta cos eta) deta",
    ));
    checks.push(table4("variation_g_61", "G", &g_vec, &dg, ""));
    checks.push(table4("variation_h1_61", "H1", &h1(), &dh1, ""));

    // The analytic dM = I R dsigma + delta(M - O).
    let mut coef: Vec<Vector> = parts.clone();
    coef[0] = Vector::new(Trihedron::IJK, r_.clone(), Atom::num(0), Atom::num(0));
    let dm_of = |c: &[Vector]| {
        c.iter()
            .enumerate()
            .fold(Vector::zero(Trihedron::IJK), |acc, (k, v)| acc.add(&v.scale(&delta(k))))
    };
    let dm = dm_of(&coef);
    let k_dm = dm.comps[2].expand();
    checks.push(check(
        "61",
        "k_component_61",
        "K|dM is the printed expression (coefficients of dtheta, deta, dgamma, dsigma1; dsigma and dnu give no vertical component)",
        &k_dm,
        &(&k_dm
            - pr("(-R*sin(theta) - a*sin(eta)*sin(theta) + (b + R*cos(mu))*sin(theta)*cos(eta) + (c - R*sin(mu))*(cos(theta)*sin(gamma) - sin(theta)*cos(gamma)*sin(eta)))*dth + (a*cos(theta)*cos(eta) + (b + R*cos(mu))*cos(theta)*sin(eta) + (c - R*sin(mu))*cos(theta)*cos(gamma)*cos(eta))*deta + (c - R*sin(mu))*(sin(theta)*cos(gamma) - cos(theta)*sin(gamma)*sin(eta))*dgam + (R*sin(mu)*cos(theta)*cos(eta) - R*cos(mu)*(sin(theta)*sin(gamma) + cos(theta)*cos(gamma)*sin(eta)))*dsig1")),
        "with the letters a, b of n° 44".into(),
    ));
    let x_om = om.comps[0].clone();
    let y_om = om.comps[1].clone();
    let [cn_i, cn_j, cn_k] = normal_components();
    let eq1_ab = om.comps[2].clone();
    let eq2_ab = d_angle(&eq1_ab, "mu").expand();
    let ident = [
        ("coefficient_dtheta_61", "the coefficient of dtheta in K|dM is y = J|OM", 1usize, y_om.clone()),
        ("coefficient_deta_61", "the coefficient of deta in K|dM is x cos theta, x = I|OM", 3, &x_om * &c_t),
        (
            "coefficient_dgamma_61",
            "the coefficient of dgamma in K|dM is (R sin mu - c) sin beta with sin beta = CN|K of n° 57",
            4,
            (&r_ * &s_mu - &c_) * &cn_k,
        ),
        (
            "coefficient_dsigma1_61",
            "the coefficient of dsigma1 in K|dM is K|dOM/dmu, zero by (2) of n° 48 (M the lowest point)",
            5,
            eq2_ab.clone(),
        ),
    ];
    for (id, statement, k, expected) in ident {
        checks.push(check(
            "61",
            id,
            statement,
            &(coeff(&k_dm, &delta(k))),
            &(coeff(&k_dm, &delta(k)) - expected),
            "exact".into(),
        ));
    }
    let deta_rel =
        &y_om * delta(1) + &x_om * &c_t * delta(3) + (&r_ * &s_mu - &c_) * &cn_k * delta(4);
    checks.push(check(
        "61",
        "condensed_deta_61",
        "K|dM = y dtheta + x cos theta deta + (R sin mu - c) sin beta dgamma + (K|dOM/dmu) dsigma1: on the contact it is the printed (deta)",
        &k_dm,
        &(&k_dm - &deta_rel - &eq2_ab * delta(5)),
        "x, y, sin beta as functions of theta, gamma, eta, mu".into(),
    ));

    // n° 62-65: the geometric method with the symbols x, y, alpha, beta.
    let (xs, ys) = (var("x"), var("y"));
    let m_o = Vector::new(Trihedron::IJK, xs.clone(), ys.clone(), Atom::num(0));
    let m_s = m_o.sub(&k_small.scale(&r_));
    let n_ab = Vector::new(Trihedron::IJK, &c_b * &s_a, -(&c_b * &c_a), s_b.clone());
    let i1 = Vector::new(Trihedron::IJK, c_a.clone(), s_a.clone(), Atom::num(0));
    let n1 = Vector::new(Trihedron::IJK, s_a.clone(), -&c_a, Atom::num(0));
    let j_small = ijk_small(1);
    let geo_disp: Vec<Vector> = vec![
        ijk(0).scale(&r_),
        ijk(0).cross(&m_o),
        k_big.cross(&m_o),
        ijk_of(&j_small.scale(&Atom::num(-1)).cross(&m_s)),
        n_ab.scale(&(&r_ * &s_mu - &c_)),
        i1.scale(&-r_.clone()),
    ];
    checks.push(vcheck(
        "62",
        "partial_displacements_62",
        "with M - O = Ix + Jy: the rotation dtheta about OI moves M by K y dtheta (printed -K mM dtheta, mM = -y) and dnu about OK by (Jx - Iy) dnu",
        &ijk_of(&geo_disp[1]).add(&ijk_of(&geo_disp[2]).scale(&var("w2"))),
        &ijk_of(&geo_disp[1]).sub(&Vector::new(Trihedron::IJK, Atom::num(0), Atom::num(0), ys.clone()))
            .add(&ijk_of(&geo_disp[2]).sub(&Vector::new(Trihedron::IJK, -&ys, xs.clone(), Atom::num(0))).scale(&var("w2"))),
        "cross products |I(M - O), |K(M - O)",
    ));
    // Contact: mu at the lowest point, a from the height equation (1).
    let kh1 = ijk_of(&h1()).comps[2].clone();
    let kg = ijk_of(&g_vec).comps[2].clone();
    let lowest = |e: &Atom| subst(&subst(e, &s_mu, &(&kh1 / wb())), &c_mu, &(&kg / wb()));
    let eq1_low = lowest(&eq1_ab).expand();
    let a_sym = var("a");
    let a_val = -subst(&eq1_low, &a_sym, &Atom::num(0)) / coeff(&eq1_low, &a_sym);
    let on_contact = |e: &Atom| subst(&lowest(e), &a_sym, &a_val);
    let geo_sub = |e: &Atom| {
        let e = subst(e, &xs, &x_om);
        let e = subst(&e, &ys, &y_om);
        let e = subst(&e, &s_a, &(&cn_i / wb()));
        let e = subst(&e, &c_a, &(-&cn_j / wb()));
        let e = subst(&e, &s_b, &cn_k);
        subst(&e, &c_b, &wb())
    };
    checks.push(check(
        "62",
        "lowest_point_on_contact_62",
        "sin mu = K|H1 / cos beta, cos mu = K|G / cos beta (cos^2 beta = CN_I^2 + CN_J^2 = (K|H1)^2 + (K|G)^2) satisfies (2) of n° 48, and a from (1) makes K|OM vanish: the substitution 'on the contact' used below",
        &(lowest(&eq2_ab) + on_contact(&eq1_ab) * var("w2")),
        &(lowest(&eq2_ab) + on_contact(&eq1_ab) * var("w2")),
        "cos beta = Wb with Wb^2 = CN_I^2 + CN_J^2".into(),
    ));
    let names = ["dsigma", "dtheta", "dnu", "deta", "dgamma", "dsigma1"];
    let geometric_forms = [
        "I R",
        "K y (needs z = K|OM = 0)",
        "Jx - Iy",
        "|-j(M - S), M - S = Ix + Jy - kR (needs z = 0)",
        "N (R sin mu - c) (rotation about the steering axis BG)",
        "-I1 R (needs M the lowest point)",
    ];
    for k in 0..6 {
        let d = coef[k].sub(&geo_disp[k].map(|e| geo_sub(e))).map(|e| on_contact(e));
        checks.push(vcheck(
            "62",
            &format!("displacement_{}_62", DELTAS[k].1),
            &format!(
                "on the contact, the analytic partial displacement dM/d{} of n° 61 is the geometric {} of n° 62",
                &names[k][1..],
                geometric_forms[k]
            ),
            &coef[k].map(|e| on_contact(e)),
            &d,
            "x = I|OM, y = J|OM, alpha and beta from CN (n° 57)",
        ));
    }
    // Tables of n° 63, 64, 65.
    let proj =
        |axis: &Vector| -> Vec<Atom> { geo_disp.iter().map(|d| axis.dot(d).expand()).collect() };
    let tables: [(&str, &str, &Vector, [&str; 6]); 3] = [
        (
            "63",
            "table_k_63",
            &k_big,
            ["0", "y", "0", "x*cos(theta)", "(R*sin(mu) - c)*sin(beta)", "0"],
        ),
        (
            "64",
            "table_n1_64",
            &n1,
            [
                "R*sin(alpha)",
                "0",
                "-y*sin(alpha) - x*cos(alpha)",
                "sin(theta)*(y*sin(alpha) + x*cos(alpha)) + R*sin(alpha)",
                "(R*sin(mu) - c)*cos(beta)",
                "0",
            ],
        ),
        (
            "65",
            "table_i1_65",
            &i1,
            [
                "R*cos(alpha)",
                "0",
                "x*sin(alpha) - y*cos(alpha)",
                "sin(theta)*(y*cos(alpha) - x*sin(alpha)) + R*cos(alpha)",
                "0",
                "-R",
            ],
        ),
    ];
    let mut rel = Vec::new();
    for (section, id, axis, printed) in tables {
        let p = proj(axis);
        let total: Atom =
            (0..6).fold(Atom::num(0), |acc, k| acc + (&p[k] - pr(printed[k])) * delta(k));
        checks.push(check(
            section,
            id,
            &format!(
                "the projections of the six displacements of n° 62 on {} are the printed table of n° {section} ({})",
                ["K", "N1 = I sin alpha - J cos alpha", "I1 = I cos alpha + J sin alpha"][rel.len()],
                printed.join("; ")
            ),
            &(0..6).fold(Atom::num(0), |acc, k| acc + &p[k] * delta(k)),
            &total,
            "N = I cos beta sin alpha - J cos beta cos alpha + K sin beta (n° 57), I1 = I cos alpha + J sin alpha".into(),
        ));
        rel.push((0..6).fold(Atom::num(0), |acc, k| acc + &p[k] * delta(k)).expand());
    }
    checks.push(check(
        "63",
        "grassmann_63_64",
        "the Grassmann products: -[K j (M - S)] = x cos theta, -[N1 j (M - S)] = sin theta (y sin alpha + x cos alpha) + R sin alpha, -[I1 j (M - S)] = sin theta (y cos alpha - x sin alpha) + R cos alpha, and [jIJ] = sin theta, [jJk] = 0, [Ijk] = 1",
        &{
            // The derived side: the six Grassmann products as computed, weighted.
            let tri = |a: &Vector, b: &Vector, c: &Vector| a.dot(&b.cross(c)).expand();
            tri(&k_big, &j_small, &m_s) * var("w1")
                + tri(&n1, &j_small, &m_s) * var("w2")
                + tri(&i1, &j_small, &m_s) * var("w3")
                + tri(&j_small, &ijk(0), &ijk(1)) * var("w4")
                + tri(&j_small, &ijk(1), &k_small) * var("w5")
                + tri(&ijk(0), &j_small, &k_small) * var("w6")
        },
        &{
            let tri = |a: &Vector, b: &Vector, c: &Vector| a.dot(&b.cross(c)).expand();
            (tri(&k_big, &j_small, &m_s) + &xs * &c_t) * var("w1")
                + (tri(&n1, &j_small, &m_s)
                    + pr("sin(theta)*(y*sin(alpha) + x*cos(alpha)) + R*sin(alpha)"))
                    * var("w2")
                + (tri(&i1, &j_small, &m_s)
                    + pr("sin(theta)*(y*cos(alpha) - x*sin(alpha)) + R*cos(alpha)"))
                    * var("w3")
                + (tri(&j_small, &ijk(0), &ijk(1)) - &s_t) * var("w4")
                + tri(&j_small, &ijk(1), &k_small) * var("w5")
                + (tri(&ijk(0), &j_small, &k_small) - &one) * var("w6")
        },
        "[A B C] = A|(|BC)".into(),
    ));
    let printed_deta = "y*dth + x*cos(theta)*deta + (R*sin(mu) - c)*sin(beta)*dgam";
    let printed_dnu = "R*sin(alpha)*dsig - (x*cos(alpha) + y*sin(alpha))*dnu + (sin(theta)*(y*sin(alpha) + x*cos(alpha)) + R*sin(alpha))*deta + (R*sin(mu) - c)*cos(beta)*dgam";
    let printed_dnu_64 = "R*sin(alpha)*dsig - (x*cos(alpha) + y*sin(alpha))*dnu + (sin(theta)*(y*sin(alpha) + x*cos(alpha)) + R*sin(alpha))*deta + R*(sin(mu) - c)*cos(beta)*dgam";
    let printed_dsig1 = "R*cos(alpha)*dsig + (x*sin(alpha) - y*cos(alpha))*dnu + (sin(theta)*(y*cos(alpha) - x*sin(alpha)) + R*cos(alpha))*deta - R*dsig1";
    checks.push(check(
        "63",
        "relation_deta_63",
        "the projection on K gives the printed (deta) of n° 63 and 66: y dtheta + x cos theta deta + (R sin mu - c) sin beta dgamma = 0",
        &rel[0],
        &(&rel[0] - pr(printed_deta)),
        format!("printed: {printed_deta}"),
    ));
    checks.push(check(
        "64",
        "relation_dnu_64_as_printed",
        "the projection on N1 gives the summary (dnu) of n° 64 as printed, with R (sin mu - c) cos beta dgamma",
        &rel[1],
        &(&rel[1] - pr(printed_dnu_64)),
        "the table of n° 64 and the (dnu) of n° 66 have (R sin mu - c) cos beta; R (sin mu - c) is not even homogeneous (R c is an area)".into(),
    ));
    checks.push(check(
        "66",
        "relation_dnu_66",
        "the projection on N1 gives the printed (dnu) of n° 66, with (R sin mu - c) cos beta dgamma",
        &rel[1],
        &(&rel[1] - pr(printed_dnu)),
        format!("printed: {printed_dnu}"),
    ));
    checks.push(check(
        "65",
        "relation_dsigma1_65",
        "the projection on I1 gives the printed (dsigma1) of n° 65 and 66",
        &rel[2],
        &(&rel[2] - pr(printed_dsig1)),
        format!("printed: {printed_dsig1}"),
    ));
    // Analytic = geometric: the analytic dM on the contact, projected on K, N1, I1 (an
    // orthonormal basis: the three projections vanish iff dM = 0), is the printed (delta).
    let n1c = n1.map(|e| geo_sub(e));
    let i1c = i1.map(|e| geo_sub(e));
    let dm_c = dm.map(|e| on_contact(e));
    let analytic_rel = [k_big.dot(&dm_c), n1c.dot(&dm_c), i1c.dot(&dm_c)];
    let printed_rel = [pr(printed_deta), pr(printed_dnu), pr(printed_dsig1)];
    let diffs: Vec<Atom> =
        (0..3).map(|i| &analytic_rel[i] - on_contact(&geo_sub(&printed_rel[i]))).collect();
    let perturbed = crate::falsify::perturb(&analytic_rel, |d| {
        (0..3).all(|i| is_zero_mod(&(&d[i] - on_contact(&geo_sub(&printed_rel[i])))))
    });
    checks.push(Check {
        perturbed: Some(crate::Perturbed { what: format!("{} (the analytic dM's projections)", perturbed.what), ..perturbed }),
        section: "66".into(),
        id: "analytic_equals_geometric_66".into(),
        statement: "on the contact, the analytic dM of n° 61 projected on K, N1, I1 (orthonormal, so the three projections vanish iff dM = 0) gives exactly the three relations (delta) of n° 66: both methods determine the same deta, dnu, dsigma1".into(),
        holds: diffs.iter().all(is_zero_mod),
        detail: format!(
            "differences reduced: [{}]",
            diffs.iter().map(|d| if is_zero_mod(d) { "0".to_string() } else { "nonzero".to_string() }).collect::<Vec<_>>().join(", ")
        ),
    });

    // n° 66: (I) and the steady state (2), from (delta) solved for deta, dnu, dsigma1.
    let sol = solve_linear(&printed_rel, &[DELTAS[3].0, DELTAS[2].0, DELTAS[5].0]);
    let i_printed = [
        ("d_eta_d_theta", "-y/(x*cos(theta))", 0usize, 1usize),
        (
            "d_nu_d_theta",
            "-y*(sin(theta)*(x*cos(alpha) + y*sin(alpha)) + R*sin(alpha))/(x*cos(theta)*(x*cos(alpha) + y*sin(alpha)))",
            1,
            1,
        ),
        ("d_eta_d_gamma", "-(R*sin(mu) - c)*sin(beta)/(x*cos(theta))", 0, 4),
        (
            "d_nu_d_gamma",
            "(R*sin(mu) - c)/(x*cos(alpha) + y*sin(alpha))*(cos(beta) - sin(beta)*(sin(theta)*(x*cos(alpha) + y*sin(alpha)) + R*sin(alpha))/(x*cos(theta)))",
            1,
            4,
        ),
        ("steady_n", "R*sin(alpha)/(x*cos(alpha) + y*sin(alpha))", 1, 0),
        ("steady_sigma1_rate", "x/(x*cos(alpha) + y*sin(alpha))", 2, 0),
    ];
    let mut formulas: Vec<Formula> = Vec::new();
    let wb_val = (sq(&cn_i) + sq(&cn_j)).pow(Atom::num(1) / Atom::num(2));
    let emit = |e: &Atom| with_ab(&subst(&geo_sub(e), &wb(), &wb_val));
    for (name, printed, unknown, known) in i_printed {
        let derived = coeff(&sol[unknown], &delta(known));
        let (section, id, what) = if name.starts_with("steady") {
            (
                "66",
                format!("{name}_2_66"),
                format!("the steady state (2) (p = gamma' = eta' = 0): {name} / s = {printed}"),
            )
        } else {
            ("66", format!("{name}_i_66"), format!("(I): {name} = {printed}, from (delta) with the other fundamental displacements zero"))
        };
        checks.push(check(
            section,
            &id,
            &what,
            &derived,
            &(&derived - pr(printed)),
            "Cramer's rule on the printed (delta) with symbols x, y, alpha, beta".into(),
        ));
        formulas.push(formula(
            name,
            "66",
            &format!("{name} of n° 66 ({printed}), with x = I|OM, y = J|OM, alpha, beta of n° 57; at a solution of the contact equations."),
            &emit(&pr(printed)),
        ));
    }
    let eq1 = with_ab(&eq1_ab).expand();
    let d1 = |q: &str| d_angle(&eq1, q);
    checks.push(check(
        "66",
        "implicit_d_eta_d_theta_66",
        "implicit differentiation of the contact equations (mu drops out since d(K|OM)/dmu = 0 by (2)): -(dK|OM/dtheta)/(dK|OM/deta) = -y/(x cos theta), the (I) dη/dθ",
        &(-d1("theta") / d1("sigma") + with_ab(&y_om) / (with_ab(&x_om) * &c_t)),
        &(-d1("theta") / d1("sigma") + with_ab(&y_om) / (with_ab(&x_om) * &c_t)),
        "exact identity in theta, gamma, eta, mu".into(),
    ));
    checks.push(check(
        "66",
        "implicit_d_eta_d_gamma_66",
        "implicit differentiation: -(dK|OM/dgamma)/(dK|OM/deta) = -(R sin mu - c) sin beta/(x cos theta), the (I) dη/dγ",
        &(-d1("gamma") / d1("sigma") + (&r_ * &s_mu - &c_) * &cn_k / (with_ab(&x_om) * &c_t)),
        &(-d1("gamma") / d1("sigma") + (&r_ * &s_mu - &c_) * &cn_k / (with_ab(&x_om) * &c_t)),
        "exact identity in theta, gamma, eta, mu".into(),
    ));

    // n° 66 bis: the front wheel's rates.
    let (p, n, etap, gp, s1p) = (var("p"), var("n"), var("etap"), var("gp"), var("sig1p"));
    let (p1, s1, n1r) = (var("p1"), var("s1"), var("n1"));
    let j1_big = Vector::new(Trihedron::IJK, -&s_a, c_a.clone(), Atom::num(0));
    let (st1, ct1) = (-&s_b, c_b.clone());
    let j1 = j1_big.scale(&ct1).add(&k_big.scale(&st1));
    let k1 = j1_big.scale(&-&st1).add(&k_big.scale(&ct1));
    let j1c = j1_big.map(|e| geo_sub(e));
    let g_proj = [
        (i1c.dot(&g_vec), -s_mu.clone(), "G|I1 = -sin mu (the angle G I1 is mu + pi/2)"),
        (j1c.dot(&g_vec), &c_mu * &s_b, "G|J1 = -cos mu sin theta1 = cos mu sin beta"),
        (k_big.dot(&g_vec), &c_mu * &c_b, "G|K = cos mu cos theta1 = cos mu cos beta"),
    ];
    for (k, (lhs, rhs, what)) in g_proj.into_iter().enumerate() {
        checks.push(check(
            "66 bis",
            &format!("projection_g_{}_66bis", ["i1", "j1", "k"][k]),
            &format!("on the contact, {what}"),
            &on_contact(&lhs),
            &on_contact(&(&lhs - geo_sub(&rhs))),
            "so G = -I1 sin mu + k1 cos mu in the front wheel's plane".into(),
        ));
    }
    checks.push(check(
        "66 bis",
        "projection_j_66bis",
        "j|I1 = cos theta sin alpha, j|J1 = cos theta cos alpha, j|K = sin theta (spherical triangle j J I1, fig. 15b)",
        &(j_small.dot(&i1) * var("w1")
            + j_small.dot(&j1_big) * var("w2")
            + j_small.dot(&k_big) * var("w3")),
        &((j_small.dot(&i1) - &c_t * &s_a) * var("w1")
            + (j_small.dot(&j1_big) - &c_t * &c_a) * var("w2")
            + (j_small.dot(&k_big) - &s_t) * var("w3")),
        "exact".into(),
    ));
    let g_dec = i1.scale(&-s_mu.clone()).add(&k1.scale(&c_mu));
    let lhs = i1.scale(&p1).add(&j1.scale(&s1)).add(&k_big.scale(&n1r));
    let rhs = ijk(0)
        .scale(&p)
        .add(&k_big.scale(&n))
        .add(&j_small.scale(&-etap.clone()))
        .add(&g_dec.scale(&gp))
        .add(&j1.scale(&s1p));
    let identity = lhs.sub(&rhs);
    let sys_printed = [
        "p1 - (p*cos(alpha) - etap*cos(theta)*sin(alpha) - gp*sin(mu))",
        "s1*cos(theta1) - (-p*sin(alpha) - etap*cos(theta)*cos(alpha) - gp*cos(mu)*sin(theta1) + sig1p*cos(theta1))",
        "s1*sin(theta1) + n1 - (n - etap*sin(theta) + gp*cos(theta1)*cos(mu) + sig1p*sin(theta1))",
    ];
    let sys_derived = [i1.dot(&identity), j1_big.dot(&identity), k_big.dot(&identity)];
    checks.push(check(
        "66 bis",
        "system_i_66bis",
        "the vector identity (2) I1 p1 + j1 s1 + K n1 = I p + K n - j eta' + G gamma' + j1 sigma1' projected on I1, J1, K is the printed system (I) (the OCR's tau', r' read eta')",
        &((0..3).fold(Atom::num(0), |acc, i| acc + &sys_derived[i] * var(&format!("w{i}")))),
        &((0..3).fold(Atom::num(0), |acc, i| acc + (&sys_derived[i] - pr(sys_printed[i])) * var(&format!("w{i}")))),
        "G = -I1 sin mu + k1 cos mu (checks projection_g_*), theta1 = -beta".into(),
    ));
    let steady =
        |e: &Atom| [&p, &gp, &etap].iter().fold(e.clone(), |acc, v| subst(&acc, v, &Atom::num(0)));
    let p1_val = &p1 - steady(&pr(sys_printed[0]));
    let s1_val = (&s1 * &c_b - steady(&pr(sys_printed[1]))) / &c_b;
    let n1_val = -steady(&subst(&pr(sys_printed[2]), &s1, &s1_val)) + &n1r;
    checks.push(check(
        "66 bis",
        "steady_ii_66bis",
        "in the steady state (p = gamma' = eta' = 0) the system (I) gives the printed (II): p1 = 0, s1 = sigma1', n1 = n",
        &(&p1_val * var("w0") + &s1_val * var("w1") + &n1_val * var("w2")),
        &(&p1_val * var("w0")
            + (&s1_val - &s1p) * var("w1")
            + (&n1_val - &n) * var("w2")),
        "solved for p1, s1, n1".into(),
    ));

    // n° 68: the fixation paradox.
    let fix = |e: &Atom| {
        let e = subst(e, &delta(0), &-delta(3));
        let e = subst(&e, &delta(4), &Atom::num(0));
        subst(&e, &delta(5), &Atom::num(0))
    };
    let fixed: Vec<Atom> = printed_rel.iter().map(|e| fix(e).expand()).collect();
    let fixed_printed = [
        "y*dth + x*cos(theta)*deta",
        "-(x*cos(alpha) + y*sin(alpha))*dnu + sin(theta)*(x*cos(alpha) + y*sin(alpha))*deta",
        "(x*sin(alpha) - y*cos(alpha))*dnu - sin(theta)*(x*sin(alpha) - y*cos(alpha))*deta",
    ];
    checks.push(check(
        "68",
        "fixed_equations_68",
        "with dsigma = -deta (the pedals held), dgamma = dsigma1 = 0, the equations (delta) become the three printed ones",
        &((0..3).fold(Atom::num(0), |acc, i| acc + &fixed[i] * var(&format!("w{i}")))),
        &((0..3).fold(Atom::num(0), |acc, i| acc + (&fixed[i] - pr(fixed_printed[i])) * var(&format!("w{i}")))),
        "(delta) of n° 66 with symbols x, y, alpha, beta".into(),
    ));
    let unknowns = [delta(1), delta(3), delta(2)];
    let mat: Vec<Vec<Atom>> =
        (0..3).map(|i| (0..3).map(|j| coeff(&fixed[i], &unknowns[j])).collect()).collect();
    let minor = &mat[0][0] * &mat[1][2] - &mat[0][2] * &mat[1][0];
    // The derived coefficient of dnu in the second fixed equation scaled: the last two
    // equations are then no longer proportional and the determinant no longer vanishes.
    let rank_perturbed = crate::Perturbed {
        what: format!(
            "the derived coefficient of dnu in the second fixed equation scaled by {}",
            crate::falsify::FACTOR
        ),
        holds: {
            let mut m = mat.clone();
            m[1][2] = &m[1][2] * crate::falsify::factor();
            is_zero_mod(&det3(&m))
        },
    };
    checks.push(Check {
        perturbed: Some(rank_perturbed),
        ..check(
        "68",
        "rank_two_68",
        "the matrix of the fixed equations in (dtheta, deta, dnu) has a zero determinant (the last two equations are proportional), so dtheta stays free",
        &det3(&mat),
        &det3(&mat),
        format!("the minor of the first two equations in (dtheta, dnu) is {} (not identically zero: rank 2)", show(&minor.expand())),
    )
    });
    // The minor with the second equation's dnu coefficient dropped (a coefficient of the derived
    // fixed equations zeroed): it must then vanish, and the check (not identically zero) fail.
    let minor_perturbed = crate::Perturbed {
        what: "the derived coefficient of dnu in the second fixed equation set to 0".to_string(),
        holds: !is_zero_mod(&(&mat[0][0] * Atom::num(0) - &mat[0][2] * &mat[1][0])),
    };
    checks.push(Check {
        perturbed: Some(minor_perturbed),
        section: "68".into(),
        id: "rank_two_minor_68".into(),
        statement: "the first two fixed equations are independent: their minor in (dtheta, dnu), -y (x cos alpha + y sin alpha), is not identically zero".into(),
        holds: !is_zero_mod(&minor),
        detail: format!("minor: {}", show(&minor.expand())),
    });
    checks.push(check(
        "68",
        "reduced_system_68",
        "the second fixed equation divided by (x cos alpha + y sin alpha) is the printed -dnu + sin theta deta = 0",
        &(&fixed[1] / pr("x*cos(alpha) + y*sin(alpha)")),
        &(&fixed[1] / pr("x*cos(alpha) + y*sin(alpha)") - pr("-dnu + sin(theta)*deta")),
        "exact".into(),
    ));

    // n° 69: the rest equilibrium.
    let (ep, epp) = (var("etap"), var("etapp"));
    let total = |f: &Atom| {
        d_angle(f, "theta")
            + d_angle(f, "sigma") * &ep
            + f.derivative(ep.get_symbol().expect("symbol")) * &epp
    };
    let z_cg = pr("(R + xg*sin(sigma1) + zg*cos(sigma1))*cos(theta)");
    let zt = d_angle(&z_cg, "theta");
    let ze = d_angle(&z_cg, "sigma");
    let chain = d_angle(&zt, "theta")
        + Atom::num(2) * d_angle(&zt, "sigma") * &ep
        + d_angle(&ze, "sigma") * sq(&ep)
        + &ze * &epp;
    checks.push(check(
        "69",
        "chain_rule_3_69",
        "with Z = (R + x sin eta1 + z cos eta1) cos theta (1) and eta1 = eta - eta0 a function of theta, the second total derivative is the printed (3): Z_theta,theta + 2 Z_eta,theta eta' + Z_eta,eta eta'^2 + Z_eta eta''",
        &(total(&total(&z_cg))),
        &(total(&total(&z_cg)) - &chain),
        "x, z of the centre of gravity are the symbols xg, zg".into(),
    ));
    let x_cg = pr("xg*cos(sigma1) - zg*sin(sigma1)");
    checks.push(check(
        "69",
        "second_derivative_69",
        "at theta = 0 with eta' = 0, d2Z/dtheta2 = -Z + X eta'' with X = x cos eta1 - z sin eta1 the current abscissa of G",
        &(zero_theta(&subst(&total(&total(&z_cg)), &ep, &Atom::num(0))) + zero_theta(&z_cg)),
        &(zero_theta(&subst(&total(&total(&z_cg)), &ep, &Atom::num(0))) + zero_theta(&z_cg) - &x_cg * &epp),
        "exact".into(),
    ));
    // eta' = -y/(x cos theta) along the contact at fixed gamma; mu' from (2) of n° 48.
    // With the letters a, b: the height equation (1) eliminates a in the particular case.
    let f_eta = -&y_om / (&x_om * &c_t);
    let eq2 = eq2_ab.clone();
    let mu_p = -(d_angle(&eq2, "theta") + d_angle(&eq2, "sigma") * &f_eta) / d_angle(&eq2, "mu");
    let eta_pp = d_angle(&f_eta, "theta")
        + d_angle(&f_eta, "sigma") * &f_eta
        + d_angle(&f_eta, "mu") * &mu_p;
    // The particular case of n° 69: theta = 0, M at E (c = R sin mu), lowest point at theta = 0.
    let case_mu = |e: &Atom| {
        let e = subst(&zero_theta(e), &c_, &(&r_ * &s_mu));
        let e = subst(&e, &s_mu, &(&s_e * &c_g / w50()));
        subst(&e, &c_mu, &(&c_e / w50()))
    };
    let eq1_case = case_mu(&eq1_ab).expand();
    let a_case = -subst(&eq1_case, &a_sym, &Atom::num(0)) / coeff(&eq1_case, &a_sym);
    let case = |e: &Atom| subst(&case_mu(e), &a_sym, &a_case);
    // The particular case leaves a literal 0: the falsification scales a symbol of the derived
    // eta' before it.
    let perturbed = crate::falsify::perturb_one(&f_eta, |d| is_zero_mod(&case(d)));
    checks.push(crate::falsify::with_perturbation(
        check(
            "69",
            "eta_prime_zero_69",
            "in the particular case R sin mu - c = 0 at theta = 0, (I) gives eta' = -y/(x cos theta) = 0 (y = -(R sin mu - c) sin gamma)",
            &case(&f_eta),
            &case(&f_eta),
            "c replaced by R sin mu, mu the lowest point at theta = 0, a from (1)".into(),
        ),
        Some(crate::Perturbed { what: format!("{} (eta' before the particular case is put in)", perturbed.what), ..perturbed }),
    ));
    let tan_form = pr("tan(mu) - tan(eta)*cos(gamma) - tan(theta)*sin(gamma)/cos(eta)");
    let mu_p_over = -(d_angle(&tan_form, "theta") + d_angle(&tan_form, "sigma") * &ep);
    let printed9 = pr("etap*cos(gamma)/cos(eta)^2 + sin(gamma)/(cos(theta)^2*cos(eta))");
    checks.push(check(
        "69",
        "mu_prime_9_69",
        "differentiating (2) of n° 48, tan mu = tan eta cos gamma + tan theta sin gamma / cos eta, along theta gives the printed (9) mu'/cos^2 mu = eta' (d tan eta/d eta) cos gamma + sin gamma/(cos^2 theta cos eta)",
        &mu_p_over,
        &(&mu_p_over - &printed9),
        "the derivative of 1/cos eta is missing from (9): the full form has + eta' tan theta sin gamma sin eta / cos^2 eta, which vanishes at theta = 0 where (9) is used".into(),
    ));
    checks.push(check(
        "69",
        "mu_prime_9_at_theta0_69",
        "at theta = 0, where the memoir uses it, the printed (9) is exact",
        &zero_theta(&(&mu_p_over - &printed9)),
        &zero_theta(&(&mu_p_over - &printed9)),
        "exact".into(),
    ));
    checks.push(check(
        "69",
        "mu_prime_eq2_69",
        "mu' from (2) of n° 48 in the form K|dOM/dmu = 0 agrees with the derivative of the tan form (9) at theta = 0 on the lowest point",
        &case(&(subst(&(&mu_p_over * sq(&c_mu)), &ep, &f_eta) - &mu_p)),
        &case(&(subst(&(&mu_p_over * sq(&c_mu)), &ep, &f_eta) - &mu_p)),
        "both implicit derivatives, at theta = 0, c = R sin mu".into(),
    ));
    let lam = zero_theta(&x_om);
    let derived_form = pr("R*cos(mu)^3*sin(gamma)^2/cos(eta)") / &lam;
    let printed_form = pr("R*cos(mu)^3*sin(gamma)/cos(eta)") / &lam;
    checks.push(check(
        "69",
        "eta_second_69_as_printed",
        "in the particular case (theta = 0, R sin mu = c, eta' = 0) eta'' is the printed R cos^3 mu sin gamma / (lambda cos eta), lambda = OM = x",
        &case(&(&eta_pp - &printed_form)),
        &case(&(&eta_pp - &printed_form)),
        "eta'' = d/dtheta(-y/(x cos theta)) = -(dy/dtheta)/x with dy/dtheta = (J|dOM/dmu) mu' = -R cos mu sin gamma * cos^2 mu sin gamma/cos eta: the factor sin gamma comes twice (once from J|H1, once from mu' of (9)); the print has one".into(),
    ));
    checks.push(check(
        "69",
        "eta_second_69",
        "in the particular case eta'' = R cos^3 mu sin^2 gamma / (lambda cos eta) (derived)",
        &case(&(&eta_pp - &derived_form)),
        &case(&(&eta_pp - &derived_form)),
        "c = R sin mu, mu the lowest point at theta = 0 and a from the height equation (1): the term of y' in z = K|OM (y' = -z + (J|dOM/dmu) mu') vanishes only on the ground".into(),
    ));

    // Emitted formulas.
    for (i, axis) in ["i", "j", "k"].iter().enumerate() {
        for (k, (_, q)) in DELTAS.iter().enumerate() {
            formulas.push(formula(
                &format!("dm_{axis}_{q}"),
                "61",
                &format!("{}|dM/d{q}: component on {} of the displacement of the front wheel's point M per unit d{q} (m/rad), analytic method of n° 61 (no contact condition imposed).", axis.to_uppercase(), axis.to_uppercase()),
                &with_ab(&coef[k].comps[i]),
            ));
        }
    }
    formulas.push(formula(
        "eta_second",
        "69",
        "eta'' = d2 eta/d theta2 (1/rad) along the contact at fixed steer: the theta-derivative of eta' = -y/(x cos theta) with mu' from (2) of n° 48 (derived, any theta).",
        &with_ab(&eta_pp),
    ));
    formulas.push(formula(
        "memoir_eta_second",
        "69",
        "eta'' as printed in n° 69: R cos^3 mu sin gamma / (lambda cos eta) with lambda = x = I|OM (1/rad); meant for theta = 0, R sin mu = c.",
        &with_ab(&(pr("R*cos(mu)^3*sin(gamma)/cos(eta)") / &x_om)),
    ));
    formulas.push(formula(
        "mu_prime",
        "69",
        "mu' = d mu/d theta (rad/rad) along the contact at fixed steer, from (2) of n° 48.",
        &with_ab(&mu_p),
    ));
    Ok(Derivation {
        model: "bicycle_kinematics".into(),
        source: file!().to_string(),
        params: geo::PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: geo::INPUTS.iter().map(|s| s.to_string()).collect(),
        formulas,
        checks,
        nominal: crate::derive::nominal::values("bicycle_kinematics"),
        horner_schemes: Vec::new(),
    })
}
