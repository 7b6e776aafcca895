//! Numerical verification of the generated bicycle kinematics (memoir n° 59–69) against
//! independent paths: finite differences of the exact contact solution, the numerical solution
//! of the analytic displacement of n° 61, the instantaneous centre of the steady motion, and
//! the rank of the fixed system of n° 68. Old-model bicycle of n° 52, the memoir's angles.

use carvallo::bicycle::kinematics::{Kinematics, RollingCondition, FD_STEP};

const DEG: f64 = std::f64::consts::PI / 180.0;

fn positions() -> Vec<(f64, f64)> {
    let mut p = Vec::new();
    for g in [20.0, 40.0, 60.0] {
        for t in [-30.0, -20.0, -10.0, 10.0, 20.0, 30.0] {
            p.push((t * DEG, g * DEG));
        }
    }
    p
}

fn close(a: f64, b: f64, rel: f64, abs: f64) -> bool {
    (a - b).abs() <= abs + rel * a.abs().max(b.abs())
}

#[test]
fn relations_i_match_finite_differences_of_the_exact_eta() {
    let k = Kinematics::old_model();
    for (t, g) in positions() {
        let r = k.relations(t, g).expect("contact");
        let [dt, dg] = k.eta_partials_fd(t, g).expect("contact");
        // Richardson-extrapolated central differences of steps 1e-3 and 5e-4: truncation
        // about 1e-12, Newton noise about 1e-11.
        assert!(
            close(r.d_eta_d_theta, dt, 1e-8, 1e-10),
            "theta {t} gamma {g}: {} vs {dt}",
            r.d_eta_d_theta
        );
        assert!(
            close(r.d_eta_d_gamma, dg, 1e-8, 1e-10),
            "theta {t} gamma {g}: {} vs {dg}",
            r.d_eta_d_gamma
        );
    }
}

#[test]
fn relations_i_and_2_match_the_analytic_system() {
    let k = Kinematics::old_model();
    for (t, g) in positions() {
        let r = k.relations(t, g).expect("contact");
        let th = k.solve_displacements(t, g, [0.0, 1.0, 0.0]).expect("contact").expect("regular");
        let gm = k.solve_displacements(t, g, [0.0, 0.0, 1.0]).expect("contact").expect("regular");
        let sg = k.solve_displacements(t, g, [1.0, 0.0, 0.0]).expect("contact").expect("regular");
        for (a, b) in [
            (r.d_eta_d_theta, th[0]),
            (r.d_nu_d_theta, th[1]),
            (r.d_eta_d_gamma, gm[0]),
            (r.d_nu_d_gamma, gm[1]),
            (r.steady_n, sg[1]),
            (r.steady_sigma1_rate, sg[2]),
            (0.0, sg[0]),
        ] {
            assert!(close(a, b, 1e-10, 1e-12), "theta {t} gamma {g}: {a} vs {b}");
        }
        let [n, s1] = k.steady_by_centre(t, g).expect("contact").expect("a centre");
        assert!(close(r.steady_n, n, 1e-10, 1e-12), "{} vs {n}", r.steady_n);
        assert!(close(r.steady_sigma1_rate, s1, 1e-10, 1e-12), "{} vs {s1}", r.steady_sigma1_rate);
    }
}

#[test]
fn nu_is_not_holonomic() {
    let k = Kinematics::old_model();
    let d = k.holonomy_defect(20.0 * DEG, 40.0 * DEG).expect("contact");
    assert!(d.abs() > 1e-3, "cross derivatives of (I) nearly equal: {d}");
}

#[test]
fn eta_is_holonomic() {
    // The same cross-derivative test on the rates of eta in (I), which are the partial
    // derivatives of the exact eta(theta, gamma): the defect is only the error of the central
    // differences (step FD_STEP = 1e-4, truncation of order h^2), at most 5e-9 at these
    // positions (1.8e-9 at theta = 20°, gamma = 40°), where nu's is -0.24.
    assert_eq!(FD_STEP, 1e-4);
    let k = Kinematics::old_model();
    for (t, g) in positions() {
        let d = k
            .cross_derivative_defect(t, g, |r| [r.d_eta_d_theta, r.d_eta_d_gamma])
            .expect("contact");
        assert!(d.abs() < 1e-7, "theta {t} gamma {g}: eta defect {d}");
    }
    let nu = k
        .cross_derivative_defect(20.0 * DEG, 40.0 * DEG, |r| [r.d_nu_d_theta, r.d_nu_d_gamma])
        .expect("contact");
    assert!(nu.abs() > 0.1, "nu defect {nu}");
    assert_eq!(nu, k.holonomy_defect(20.0 * DEG, 40.0 * DEG).expect("contact"));
}

#[test]
fn three_independent_rolling_conditions() {
    // n° 59: the three rolling conditions are independent in (deta, dnu, dsigma1) where the
    // analytic system is regular; any one dropped leaves two, and four free displacements.
    let k = Kinematics::old_model();
    for (t, g) in positions() {
        assert_eq!(k.rolling_rank(t, g, None).expect("contact"), 3, "theta {t} gamma {g}");
        assert!(k.solve_displacements(t, g, [1.0, 0.0, 0.0]).expect("contact").is_some());
        for c in [RollingCondition::I, RollingCondition::J, RollingCondition::K] {
            let r = k.rolling_rank(t, g, Some(c)).expect("contact");
            assert_eq!(r, 2, "theta {t} gamma {g}: {c:?} dropped");
        }
    }
}

#[test]
fn fixation_system_has_rank_two() {
    let k = Kinematics::old_model();
    for (t, g) in positions() {
        let (det, minor) = k.fixation_rank(t, g).expect("contact");
        assert!(det < 1e-12, "theta {t} gamma {g}: det {det}");
        assert!(minor > 1e-3, "theta {t} gamma {g}: minor {minor}");
    }
}

#[test]
fn rest_equilibrium_second_derivatives() {
    let k = Kinematics::old_model();
    let eq = k.rest_equilibrium().expect("contact");
    // The lowest frame position of n° 53 (R sin mu = c) at 61.855887779° (Newton to 1e-12 rad,
    // about 6e-11°; the memoir's slide-rule value is 61.6°): within 1e-8°, not the 1° that
    // would also accept 61.6.
    assert!((eq.gamma / DEG - 61.855_887_779).abs() < 1e-8, "gamma {}", eq.gamma / DEG);
    assert!(eq.relations.d_eta_d_theta.abs() < 1e-12);
    assert!(eq.eta_prime_fd.abs() < 1e-8, "{}", eq.eta_prime_fd);
    // Second differences of step 1e-3: truncation about 1e-7, Newton noise 1e-8.
    let r = &eq.relations;
    assert!(
        close(r.eta_second, eq.eta_second_fd, 1e-5, 1e-7),
        "{} vs {}",
        r.eta_second,
        eq.eta_second_fd
    );
    // The printed formula lacks a factor sin gamma.
    assert!(close(r.memoir_eta_second * eq.gamma.sin(), r.eta_second, 1e-9, 0.0));
    assert!(!close(r.memoir_eta_second, eq.eta_second_fd, 1e-2, 0.0));
    let st = k.rest_stability(&eq, 0.45, 0.75).expect("contact");
    assert!(close(st.d2z, st.d2z_fd, 1e-5, 1e-7), "{} vs {}", st.d2z, st.d2z_fd);
    assert!(st.d2z < 0.0 && st.d2z_memoir < 0.0);
}
