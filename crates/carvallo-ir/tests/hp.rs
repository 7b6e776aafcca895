//! High-precision evaluation: accuracy against known values (70-digit references), `atan2` in
//! every quadrant and on the axes, negative powers, correct rounding to `f64`, and agreement
//! of the `f64` interpreter with 256-bit evaluation on well-conditioned random programs.

mod common;

use astro_float::{BigFloat, Consts, Radix, RoundingMode};
use carvallo_ir::{hp, Builder, Program};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

const PREC: usize = 256;

/// Relative difference between a high-precision result and a decimal reference.
fn rel_err(x: &BigFloat, reference: &str) -> f64 {
    let mut cc = Consts::new().unwrap();
    let r = BigFloat::parse(reference, Radix::Dec, 512, RoundingMode::ToEven, &mut cc);
    assert!(!r.is_nan(), "bad reference {reference}");
    let d = x.sub(&r, 512, RoundingMode::ToEven);
    if r.is_zero() {
        return hp::to_f64(&d).abs();
    }
    hp::to_f64(&d.div(&r, 512, RoundingMode::ToEven)).abs()
}

/// A one-input program `y = OP x` (or `OP x c` for binary ops with the constant `c`).
fn unary(op: &str) -> Program {
    Program::parse(&format!("carvallo-ir 1\nmodel t\ninput x\nlet y = {op} x\noutput y = y\n"))
        .unwrap()
}

fn binary(op: &str) -> Program {
    Program::parse(&format!(
        "carvallo-ir 1\nmodel t\ninput a\ninput b\nlet y = {op} a b\noutput y = y\n"
    ))
    .unwrap()
}

/// 70-digit references (computed independently with mpmath at 70 digits).
const SQRT2: &str = "1.414213562373095048801688724209698078569671875376948073176679737990732";
const SIN1: &str = "0.8414709848078965066525023216302989996225630607983710656727517099919104";
const COS1: &str = "0.5403023058681397174009366074429766037323104206179222276700972553811004";
const TAN1: &str = "1.557407724654902230506974807458360173087250772381520038383946605698861";
const PI: &str = "3.141592653589793238462643383279502884197169399375105820974944592307816";
/// atan2(-3, -4).
const ATAN2_M3_M4: &str =
    "-2.498091544796508851659834154562180246155658808259793438109338473594304";

/// 256 bits carry about 77 digits; the references have 70. Required: 65 correct digits.
const TOL: f64 = 1e-65;

#[test]
fn known_values_to_65_digits() {
    for (op, x, reference) in
        [("sqrt", 2.0, SQRT2), ("sin", 1.0, SIN1), ("cos", 1.0, COS1), ("tan", 1.0, TAN1)]
    {
        let y = hp::eval(&unary(op), &[], &[x], PREC).unwrap();
        let e = rel_err(&y[0], reference);
        assert!(e < TOL, "{op}({x}): relative error {e:e}");
        // And the reference is not met at lower precision: the check can fail.
        let y64 = hp::eval(&unary(op), &[], &[x], 64).unwrap();
        assert!(rel_err(&y64[0], reference) > TOL, "{op} at 64 bits");
    }
    // sqrt(2) printed: the first 60 significant digits.
    let y = hp::eval(&unary("sqrt"), &[], &[2.0], PREC).unwrap();
    assert!(format!("{}", y[0]).starts_with(&SQRT2[..61]), "{}", y[0]);
}

#[test]
fn atan2_all_quadrants_and_axes() {
    let p = binary("atan2");
    let pi = |num: i32, den: i32| -> BigFloat {
        let mut cc = Consts::new().unwrap();
        let r = BigFloat::parse(PI, Radix::Dec, 512, RoundingMode::ToEven, &mut cc);
        r.mul(&BigFloat::from_i32(num, 512), 512, RoundingMode::ToEven).div(
            &BigFloat::from_i32(den, 512),
            512,
            RoundingMode::ToEven,
        )
    };
    // (y, x, expected multiple of pi as num/den)
    let cases = [
        (1.0, 1.0, 1, 4),
        (1.0, -1.0, 3, 4),
        (-1.0, -1.0, -3, 4),
        (-1.0, 1.0, -1, 4),
        (1.0, 0.0, 1, 2),
        (-1.0, 0.0, -1, 2),
        (0.0, -1.0, 1, 1),
        (0.0, 1.0, 0, 1),
        (0.0, 0.0, 0, 1),
        (2.0, -0.0, 1, 2),
    ];
    for (y, x, num, den) in cases {
        let got = &hp::eval(&p, &[], &[y, x], PREC).unwrap()[0];
        let want = pi(num, den);
        let d = hp::to_f64(&got.sub(&want, 512, RoundingMode::ToEven)).abs();
        assert!(d < TOL, "atan2({y}, {x}): error {d:e}");
        assert_eq!(hp::to_f64(got), y.atan2(x), "atan2({y}, {x}) rounded");
    }
    let got = &hp::eval(&p, &[], &[-3.0, -4.0], PREC).unwrap()[0];
    assert!(rel_err(got, ATAN2_M3_M4) < TOL);
    // Random points in every quadrant agree with f64::atan2 within 2 ulp-ish (2.5e-16 relative).
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    for _ in 0..400 {
        let (y, x): (f64, f64) = (rng.gen_range(-5.0..5.0), rng.gen_range(-5.0..5.0));
        let hp = hp::eval_f64(&p, &[], &[y, x], PREC).unwrap()[0];
        let f = y.atan2(x);
        assert!((hp - f).abs() <= 2.5e-16 * f.abs(), "atan2({y}, {x}): {hp} vs {f}");
    }
}

#[test]
fn integer_powers_including_negative() {
    let text =
        |k: i32| format!("carvallo-ir 1\nmodel t\ninput x\nlet y = powi x {k}\noutput y = y\n");
    let p = Program::parse(&text(-3)).unwrap();
    let y = hp::eval(&p, &[], &[1.5], PREC).unwrap();
    assert!(
        rel_err(&y[0], "0.2962962962962962962962962962962962962962962962962962962962962962962963")
            < TOL
    );
    for k in [-7, -2, -1, 0, 1, 2, 5, 11] {
        let p = Program::parse(&text(k)).unwrap();
        for x in [0.75, -1.25, 3.0] {
            // Powers of these x are exact or nearly so in 256 bits; f64::powi is within a few ulp.
            let h = hp::eval_f64(&p, &[], &[x], PREC).unwrap()[0];
            let f = f64::powi(x, k);
            assert!((h - f).abs() <= 1e-15 * f.abs(), "{x}^{k}: {h} vs {f}");
        }
    }
    // 0^-1 is infinite, as in f64.
    let p = Program::parse(&text(-1)).unwrap();
    assert_eq!(hp::eval_f64(&p, &[], &[0.0], PREC).unwrap()[0], f64::INFINITY);
}

#[test]
fn rounding_to_f64_is_correct() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    // Exact values come back unchanged, subnormals and extremes included.
    let ident = unary("neg");
    for x in [
        1.0,
        0.1,
        5e-324,
        f64::from_bits(0x000f_ffff_ffff_ffff),
        f64::MAX,
        f64::MIN_POSITIVE,
        1e-310,
    ] {
        assert_eq!(hp::eval_f64(&ident, &[], &[-x], PREC).unwrap()[0].to_bits(), x.to_bits());
    }
    // IEEE operations are correctly rounded, so they must agree bit for bit with rounding the
    // (here exact or 256-bit) result, including results in the subnormal range.
    for op in ["add", "sub", "mul", "div"] {
        let p = binary(op);
        for _ in 0..500 {
            let a = rng.gen_range(-4.0..4.0) * 10f64.powi(rng.gen_range(-160..160));
            let b = rng.gen_range(-4.0..4.0) * 10f64.powi(rng.gen_range(-160..160));
            let want = p.eval_f64(&[], &[a, b]).unwrap()[0];
            let got = hp::eval_f64(&p, &[], &[a, b], PREC).unwrap()[0];
            assert_eq!(got.to_bits(), want.to_bits(), "{op} {a:e} {b:e}: {got:e} vs {want:e}");
        }
    }
    let p = unary("sqrt");
    for _ in 0..500 {
        let a = rng.gen_range(0.0..4.0) * 10f64.powi(rng.gen_range(-300..300));
        assert_eq!(hp::eval_f64(&p, &[], &[a], PREC).unwrap()[0], a.sqrt(), "sqrt {a:e}");
    }
    // Ties go to even: 1 + 2^-53 -> 1 and 1 + 3 * 2^-53 -> 1 + 2^-51.
    let add = binary("add");
    let u = f64::EPSILON / 2.0;
    assert_eq!(hp::eval_f64(&add, &[], &[1.0, u], PREC).unwrap()[0], 1.0);
    assert_eq!(hp::eval_f64(&add, &[], &[1.0, 3.0 * u], PREC).unwrap()[0], 1.0 + 4.0 * u);
    // Just above a tie rounds up: 1 + 2^-53 + 2^-200.
    let p = Program::parse(
        "carvallo-ir 1\nmodel t\ninput a\ninput b\ninput c\nlet s = add a b\nlet t = add s c\noutput y = t\n",
    )
    .unwrap();
    assert_eq!(hp::eval_f64(&p, &[], &[1.0, u, 2f64.powi(-200)], PREC).unwrap()[0], 1.0 + 2.0 * u);
    // Overflow and underflow.
    let mul = binary("mul");
    assert_eq!(hp::eval_f64(&mul, &[], &[1e300, -1e300], PREC).unwrap()[0], f64::NEG_INFINITY);
    assert_eq!(hp::eval_f64(&mul, &[], &[1e-200, 1e-200], PREC).unwrap()[0], 0.0);
    assert!(hp::eval_f64(&unary("sqrt"), &[], &[-1.0], PREC).unwrap()[0].is_nan());
}

#[test]
fn errors_are_reported() {
    let p = binary("add");
    assert_eq!(
        hp::eval(&p, &[], &[1.0], PREC).unwrap_err(),
        carvallo_ir::IrError::ArgumentCount { what: "inputs", expected: 2, got: 1 }
    );
    assert_eq!(
        hp::eval(&p, &[1.0], &[1.0, 2.0], PREC).unwrap_err().to_string(),
        "wrong number of parameters: expected 0, got 1"
    );
    assert!(hp::eval(&p, &[], &[1.0, 2.0], 8).is_err());
}

#[test]
fn f64_interpreter_agrees_with_256_bits_on_well_conditioned_programs() {
    // Every step has a relative condition number of at most 3 and rounds once (1.1e-16, libm's
    // sin/cos/tan/atan2 within about one ulp); along the at most 40 steps of these programs
    // the errors mostly average out (the worst seen with this seed is about 4e-16), so
    // 1e-14, about 90 ulp, is a safe yet meaningful bound.
    const REL_TOL: f64 = 1e-14;
    let mut rng = ChaCha8Rng::seed_from_u64(0x5eed);
    let mut worst = 0.0f64;
    let mut compared = 0;
    for _ in 0..60 {
        let (p, params, inputs) = common::well_conditioned_program(&mut rng, 40);
        for _ in 0..3 {
            // The point itself and perturbations of it by at most 5 %.
            let jitter = |v: &[f64], rng: &mut ChaCha8Rng| -> Vec<f64> {
                v.iter().map(|x| x * rng.gen_range(0.95..1.05)).collect()
            };
            let (pa, ia) = (jitter(&params, &mut rng), jitter(&inputs, &mut rng));
            let f = p.eval_f64(&pa, &ia).unwrap();
            let h = hp::eval_f64(&p, &pa, &ia, PREC).unwrap();
            for (a, b) in f.iter().zip(&h) {
                assert!(b.is_finite() && *b > 0.0, "value {b} out of the generator's range\n{p}");
                let e = (a - b).abs() / b.abs();
                worst = worst.max(e);
                assert!(e <= REL_TOL, "f64 {a} vs hp {b}: relative error {e:e}\n{p}");
                compared += 1;
            }
        }
    }
    assert!(compared >= 500);
    // The comparison is not vacuous: f64 rounding is visible.
    assert!(worst > 0.0);
    eprintln!("worst relative error of the f64 interpreter: {worst:e} over {compared} outputs");
}

#[test]
fn builder_programs_evaluate_consistently() {
    // $E = \sin\theta \, g / R - 1.5 n^2$ at a known point, both ways.
    let mut b = Builder::new("hoop");
    let (r, g) = (b.param("R"), b.param("g"));
    let (th, n) = (b.input("theta"), b.input("n"));
    let s = b.sin(th);
    let q = b.div(g, r);
    let t = b.mul(s, q);
    let c = b.constant(1.5);
    let n2 = b.powi(n, 2);
    let u = b.mul(c, n2);
    let e = b.sub(t, u);
    b.output("e", e);
    let p = b.finish();
    let want = 0.3f64.sin() * 9.81 / 0.5 - 1.5 * 0.7 * 0.7;
    let f = p.eval_f64(&[0.5, 9.81], &[0.3, 0.7]).unwrap()[0];
    let h = hp::eval_f64(&p, &[0.5, 9.81], &[0.3, 0.7], PREC).unwrap()[0];
    assert!((f - want).abs() <= 1e-14 * want.abs());
    assert!((h - want).abs() <= 1e-14 * want.abs());
}
