//! The straight-running bicycle of memoir n° 107–122: every check of the derivation has its
//! expected outcome (the n° 116 table sums equal the n° 117 closed forms; every table entry, by
//! part and by origin, equals the general model's at three exact rational points, except the
//! five gamma'' entries as the OCR prints them, which have the opposite sign; the n° 122
//! closed forms; the n° 121 Routh–Hurwitz relation), and the emitted IR evaluated at the
//! constants of n° 117 gives the quartic of n° 119 as the determinant of the emitted
//! coefficients (relative 1e-12).

use crate::common;

use carvallo_codegen::derive::bicycle::straight as bicycle_straight;
use carvallo_codegen::emit::emit_program;

fn straight_running_derivation_body() {
    let t = std::time::Instant::now();
    let d = crate::derived("bicycle_straight");
    eprintln!("derived in {:?}", t.elapsed());
    for c in &d.checks {
        eprintln!("{} {}: holds = {}; {}", c.section, c.id, c.holds, c.detail);
    }
    // Findings: the five gamma'' entries of the (dT/dq')' rows as the OCR prints them.
    let findings = [
        "fall_frame_gamma2_as_printed",
        "fall_front_wheel_gamma2_as_printed",
        "bar_frame_gamma2_as_printed",
        "bar_rear_wheel_gamma2_as_printed",
        "bar_front_wheel_gamma2_as_printed",
    ];
    common::assert_checks(&d.checks, &findings);
    let prog = emit_program(d).expect("emission");
    // n° 117: R, l, c_1, eta = 25°, e, h, mu, mu1, A + 2 A1, C, L; g = 9.81.
    let params =
        [0.38, 1.10, 0.08, 25f64.to_radians(), 0.20, 1.0, 70.0, 5.0, 100.0, 4.0, 14.0, 9.81];
    let names: Vec<&str> = prog.outputs.iter().map(|o| o.name.as_str()).collect();
    for s in [3.0, 8.2, 9.5] {
        let o = prog.eval_f64(&params, &[s]).expect("eval");
        let at = |n: &str| o[names.iter().position(|x| *x == n).expect("output")];
        let c: Vec<f64> = bicycle_straight::COEFFS.iter().map(|n| at(n)).collect();
        // Time-scaled coefficients (T = s t): divide the k-th derivative's coefficient by s^(2-k).
        let sc = |i: usize| c[i] / s.powi([0, 1, 2][i % 3]);
        for lam in [-0.7, 0.3, 1.9] {
            let tri = |b: usize| sc(b) * lam * lam + sc(b + 1) * lam + sc(b + 2);
            let det = tri(0) * tri(9) - tri(3) * tri(6);
            let poly: f64 = (0..5).map(|k| at(&format!("quartic{k}")) * lam.powi(k)).sum();
            let scale: f64 = (0..5).map(|k| (at(&format!("quartic{k}")) * lam.powi(k)).abs()).sum();
            assert!((poly - det).abs() <= 1e-12 * scale, "quartic at s={s}, lambda={lam}");
        }
    }
    eprintln!("bicycle_straight IR: {} ops", prog.op_count().total);
}

#[test]
fn straight_running_derivation() {
    crate::on_symbolica_thread(straight_running_derivation_body);
}
