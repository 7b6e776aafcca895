//! Tests of the emission of symbolica expressions into IR (`carvallo_codegen::emit`).
//!
//! The main property: the emitted program, run by the IR's f64 interpreter
//! (`Program::eval_f64`), agrees with symbolica's own numerical evaluation of the same
//! expression at seeded random points, for hand-written expressions and for every formula of
//! the hoop derivation. Also: correct rounding of exact rationals (checked against Rust's
//! correctly rounded decimal parser), errors naming the offending sub-expression, the shape of
//! the lowering (one division per product, no negation where a subtraction does), and byte
//! stability of every rendered file.

use std::collections::{BTreeMap, HashMap};

use carvallo_codegen::emit::{
    count_ops, emit_expr, emit_program, rational_to_f64, render_checks, render_markdown, EmitError,
    Expr,
};
use carvallo_codegen::{Check, Derivation, Formula};
use carvallo_ir::{Builder, Op, Program};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use symbolica::atom::{Atom, AtomCore};
use symbolica::domains::float::Float;
use symbolica::parse;
use symbolica::prelude::RealLike;

/// Relative tolerance between the IR interpreter and symbolica's f64 evaluation, applied as
/// `|ir - sym| <= REL_TOL * max(|sym|, ABS_FLOOR)`. Both evaluate in f64 with differently
/// ordered operations; the expressions below have at most a few dozen operations and the
/// sample points avoid cancellation-prone regions, so a few ulps of disagreement times a
/// small condition number stays far below this.
const REL_TOL: f64 = 1e-11;
/// Scale below which the comparison becomes absolute (values near zero after cancellation).
const ABS_FLOOR: f64 = 1.0;

use crate::on_symbolica_thread;

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= REL_TOL * b.abs().max(ABS_FLOOR)
}

/// A one-formula derivation over the given parameters and inputs.
fn single(params: &[&str], inputs: &[&str], expr: Atom) -> Derivation {
    Derivation {
        model: "test".to_string(),
        source: "codegen/tests/emit.rs".to_string(),
        params: params.iter().map(|s| s.to_string()).collect(),
        inputs: inputs.iter().map(|s| s.to_string()).collect(),
        formulas: vec![Formula {
            name: "f".to_string(),
            section: "0".to_string(),
            description: "A test formula.".to_string(),
            expr,
        }],
        checks: vec![],
        nominal: Vec::new(),
        horner_schemes: Vec::new(),
    }
}

/// Symbolica's f64 value of `expr` with the symbols named in `values` (by name without
/// namespace) set to those values.
fn symbolica_eval(expr: &Atom, values: &BTreeMap<String, f64>) -> f64 {
    let mut map: HashMap<Atom, f64> = HashMap::new();
    for s in expr.get_all_symbols(false) {
        let name = s.get_stripped_name().to_string();
        let v = *values.get(&name).unwrap_or_else(|| panic!("no test value for symbol {name}"));
        map.insert(s.to_atom(), v);
    }
    expr.evaluate(&map).unwrap_or_else(|e| panic!("symbolica cannot evaluate {expr}: {e:?}"))
}

/// Compares the emitted program of `d` with symbolica at `n` seeded random points; `ranges`
/// gives the sampling interval of every parameter and input by name.
fn compare_with_symbolica(
    d: &Derivation,
    ranges: &BTreeMap<&str, (f64, f64)>,
    n: usize,
    seed: u64,
) {
    let program = emit_program(d).unwrap_or_else(|e| panic!("emission failed: {e}"));
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    for _ in 0..n {
        let mut values = BTreeMap::new();
        for name in d.params.iter().chain(&d.inputs) {
            let (lo, hi) = ranges[name.as_str()];
            values.insert(name.clone(), rng.gen_range(lo..hi));
        }
        let params: Vec<f64> = d.params.iter().map(|p| values[p]).collect();
        let inputs: Vec<f64> = d.inputs.iter().map(|i| values[i]).collect();
        let got = program.eval_f64(&params, &inputs).expect("the interpreter runs");
        for (f, ir) in d.formulas.iter().zip(&got) {
            let sym = symbolica_eval(&f.expr, &values);
            assert!(
                close(*ir, sym),
                "{}: IR gives {ir:e}, symbolica {sym:e} at {values:?} (relative tolerance {REL_TOL:e})",
                f.name
            );
        }
    }
}

#[test]
fn hand_written_expressions_match_symbolica() {
    on_symbolica_thread(hand_written_expressions_match_symbolica_body);
}

fn hand_written_expressions_match_symbolica_body() {
    let cases = [
        "3/2*g*sin(theta)/R",
        "4/3*n*s*cos(theta) + 2/3*g*sin(theta)/R + n^2*sin(theta)*cos(theta)",
        "-x - y - 1/7",
        "x^5 - 3*x^-3 + x^(1/2) - y^(-1/2) + x^(3/2)*y^(-5/2)",
        "(x + y)^3/(x*y^2*(1 + x^2)) - 1",
        "sqrt(x^2 + y^2) + cos(x*y)^2 + sin(x*y)^2",
        "tan(x)*y - 12345678901234567890123/1000000000000000000000*x",
        "(1 + x)^-1 + 2/(x + y)",
        "8/3*n*s*sin(theta) - 2/3*g*cos(theta)/R + n^2 + 8/3*s^2",
    ];
    let ranges: BTreeMap<&str, (f64, f64)> = [
        ("g", (9.0, 10.0)),
        ("R", (0.2, 2.0)),
        ("theta", (-1.2, 1.2)),
        ("n", (-3.0, 3.0)),
        ("s", (-3.0, 3.0)),
        ("x", (0.5, 2.0)),
        ("y", (0.5, 2.0)),
    ]
    .into_iter()
    .collect();
    for (i, case) in cases.iter().enumerate() {
        let d = single(&["R", "g"], &["theta", "n", "s", "x", "y"], parse!(case));
        compare_with_symbolica(&d, &ranges, 200, 0x5eed + i as u64);
    }
}

#[test]
fn hoop_formulas_match_symbolica() {
    on_symbolica_thread(hoop_formulas_match_symbolica_body);
}

fn hoop_formulas_match_symbolica_body() {
    let d = crate::derived("hoop");
    assert!(!d.formulas.is_empty(), "the hoop derivation has formulas");
    // Away from theta = 0 and +-pi/2 (some formulas divide by sin or cos theta).
    let ranges: BTreeMap<&str, (f64, f64)> = [
        ("R", (0.2, 2.0)),
        ("g", (9.0, 10.0)),
        ("mu", (0.5, 5.0)),
        ("theta", (0.2, 1.3)),
        ("p", (-2.0, 2.0)),
        ("q", (-2.0, 2.0)),
        ("r", (-2.0, 2.0)),
        ("n", (-3.0, 3.0)),
        ("s", (-3.0, 3.0)),
    ]
    .into_iter()
    .collect();
    compare_with_symbolica(d, &ranges, 100, 0x4009);
}

/// Precision of the high-precision comparison, in bits.
const HP_BITS: u32 = 256;
/// Relative tolerance of the high-precision comparison, applied like [`REL_TOL`]. At 256 bits
/// both evaluations are exact to far below f64 resolution; what remains is the rounding of the
/// IR's constants to f64 (half an ulp each, about 1.1e-16 relative) times the small condition
/// numbers of these formulas at the sampled points.
const HP_REL_TOL: f64 = 1e-14;

#[test]
fn hoop_formulas_match_symbolica_in_high_precision() {
    on_symbolica_thread(hoop_formulas_match_symbolica_in_high_precision_body);
}

fn hoop_formulas_match_symbolica_in_high_precision_body() {
    let d = crate::derived("hoop");
    let program = emit_program(d).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(0x4010);
    for _ in 0..20 {
        let mut values = BTreeMap::new();
        for name in d.params.iter().chain(&d.inputs) {
            let (lo, hi) = match name.as_str() {
                "R" => (0.2, 2.0),
                "g" => (9.0, 10.0),
                "mu" => (0.5, 5.0),
                "theta" => (0.2, 1.3),
                _ => (-3.0, 3.0),
            };
            values.insert(name.clone(), rng.gen_range(lo..hi));
        }
        let params: Vec<f64> = d.params.iter().map(|p| values[p]).collect();
        let inputs: Vec<f64> = d.inputs.iter().map(|i| values[i]).collect();
        let got = carvallo_ir::hp::eval_f64(&program, &params, &inputs, HP_BITS as usize).unwrap();
        for (f, ir) in d.formulas.iter().zip(&got) {
            let mut map: HashMap<Atom, Float> = HashMap::new();
            for s in f.expr.get_all_symbols(false) {
                map.insert(s.to_atom(), Float::with_val(HP_BITS, values[s.get_stripped_name()]));
            }
            let sym = f.expr.evaluate_with_prec(&map, HP_BITS).unwrap().to_f64();
            assert!(
                (ir - sym).abs() <= HP_REL_TOL * sym.abs().max(ABS_FLOOR),
                "{}: IR at {HP_BITS} bits gives {ir:e}, symbolica {sym:e} at {values:?}",
                f.name
            );
        }
    }
}

#[test]
fn tan_and_atan2_lower_to_their_ops() {
    on_symbolica_thread(tan_and_atan2_lower_to_their_ops_body);
}

fn tan_and_atan2_lower_to_their_ops_body() {
    // Symbolica's own evaluator has no atan2, so this one is checked against Rust's f64 ops.
    let d = single(&[], &["x", "y"], parse!("atan2(y, x) + tan(x)"));
    let p = emit_program(&d).unwrap();
    assert!(p.insts.iter().any(|i| matches!(i.op, Op::Atan2(..))), "{}", p.to_text());
    assert!(p.insts.iter().any(|i| matches!(i.op, Op::Tan(..))), "{}", p.to_text());
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    for _ in 0..100 {
        let (x, y): (f64, f64) = (rng.gen_range(-2.0..2.0), rng.gen_range(-2.0..2.0));
        let got = p.eval_f64(&[], &[x, y]).unwrap()[0];
        let want = y.atan2(x) + x.tan();
        assert!(close(got, want), "atan2(y, x) + tan(x) at ({x}, {y}): {got} vs {want}");
    }
}

#[test]
fn rationals_round_correctly() {
    on_symbolica_thread(rationals_round_correctly_body);
}

fn rationals_round_correctly_body() {
    // Rust's decimal parser is correctly rounded: an independent oracle for p / 10^k.
    let mut rng = ChaCha8Rng::seed_from_u64(0xdec);
    for _ in 0..300 {
        let digits: String =
            (0..rng.gen_range(1..60)).map(|_| char::from(b'0' + rng.gen_range(0..10u8))).collect();
        let digits = format!("{}{digits}", rng.gen_range(1..10));
        let k = rng.gen_range(0..80);
        let neg = rng.gen_bool(0.5);
        let sign = if neg { "-" } else { "" };
        let text = format!("{sign}{digits}/1{}", "0".repeat(k));
        let Expr::Num(r) = Expr::from_atom(&parse!(&text)).unwrap() else {
            panic!("{text} is a number")
        };
        let want: f64 = format!("{sign}{digits}e-{k}").parse().unwrap();
        assert_eq!(rational_to_f64(&r).map(f64::to_bits), Some(want.to_bits()), "{text}");
    }
    let num = |s: &str| {
        let Expr::Num(r) = Expr::from_atom(&parse!(s)).unwrap() else { panic!("{s} is a number") };
        r
    };
    // Ties go to even: 2^53 + 1 lies halfway between 2^53 and 2^53 + 2.
    assert_eq!(rational_to_f64(&num("9007199254740993")), Some(9007199254740992.0));
    assert_eq!(rational_to_f64(&num("9007199254740995")), Some(9007199254740996.0));
    assert_eq!(rational_to_f64(&num("1/3")), Some(1.0 / 3.0));
    assert_eq!(rational_to_f64(&num("-2/3")), Some(-2.0 / 3.0));
    // Out of range: 10^400 has no finite f64; 10^-400 rounds to zero.
    assert_eq!(rational_to_f64(&num(&format!("1{}", "0".repeat(400)))), None);
    assert_eq!(rational_to_f64(&num(&format!("1/1{}", "0".repeat(400)))), Some(0.0));
    // The largest finite value and just past half an ulp beyond it.
    let max = num("179769313486231570814527423731704356798070567525844996598917476803157260780028538760589558632766878171540458953514382464234321326889464182768467546703537516986049910576551282076245490090389328944075868508455133942304583236903222948165808559332123348274797826204144723168738177180919299881250404026184124858368");
    assert_eq!(rational_to_f64(&max), Some(f64::MAX));
}

#[test]
fn big_constant_in_a_program_is_rounded_once() {
    on_symbolica_thread(big_constant_in_a_program_is_rounded_once_body);
}

fn big_constant_in_a_program_is_rounded_once_body() {
    let d = single(&[], &["x"], parse!("x*12345678901234567890123456789/1000"));
    let p = emit_program(&d).unwrap();
    let consts: Vec<f64> = p
        .insts
        .iter()
        .filter_map(|i| if let Op::Const(c) = i.op { Some(c) } else { None })
        .collect();
    let want: f64 = "12345678901234567890123456.789".parse().unwrap();
    assert_eq!(consts, vec![want], "{}", p.to_text());
}

fn emit_error(params: &[&str], inputs: &[&str], expr: &str) -> String {
    match emit_program(&single(params, inputs, parse!(expr))) {
        Ok(p) => panic!("{expr} should not emit, got\n{}", p.to_text()),
        Err(e) => e.to_string(),
    }
}

#[test]
fn errors_name_the_offending_sub_expression() {
    on_symbolica_thread(errors_name_the_offending_sub_expression_body);
}

fn errors_name_the_offending_sub_expression_body() {
    let e = emit_error(&["R"], &["x"], "R*x + zeta");
    assert!(e.contains("formula f") && e.contains("unknown symbol \"zeta\""), "{e}");
    let e = emit_error(&[], &["x"], "x + log(x)");
    assert!(e.contains("function log") && e.contains("log(x)"), "{e}");
    // exp(x) is normalised by symbolica into a power of the constant e.
    let e = emit_error(&[], &["x"], "x + exp(x)");
    assert!(e.contains("symbolic exponent"), "{e}");
    let e = emit_error(&[], &["x"], "1 + x^(1/3)");
    assert!(e.contains("exponent 1/3") && e.contains("x^(1/3)"), "{e}");
    let e = emit_error(&[], &["x", "y"], "1 + x^y");
    assert!(e.contains("symbolic exponent") && e.contains("x^y"), "{e}");
    let e = emit_error(&[], &["x"], "1 + atan2(x)");
    assert!(e.contains("atan2") && e.contains("expected 2"), "{e}");
    let e = emit_error(&[], &["x"], &format!("x + 1{}", "0".repeat(400)));
    assert!(e.contains("no finite f64 value"), "{e}");
    let mut d = single(&[], &["x"], parse!("x"));
    d.formulas.push(d.formulas[0].clone());
    let e = emit_program(&d).unwrap_err();
    assert_eq!(e, EmitError::BadName { name: "f".into(), reason: "output declared twice".into() });
    let d = single(&["x"], &["x"], parse!("x"));
    assert!(matches!(emit_program(&d), Err(EmitError::BadName { .. })));
}

fn ops_of(inputs: &[&str], expr: &str) -> (usize, BTreeMap<&'static str, usize>, Program) {
    let d = single(&[], inputs, parse!(expr));
    let p = emit_program(&d).unwrap();
    let (total, by) = count_ops(&p);
    (total, by, p)
}

#[test]
fn lowering_shapes() {
    on_symbolica_thread(lowering_shapes_body);
}

fn lowering_shapes_body() {
    // All negative exponents of a product go into one division.
    let (_, by, p) = ops_of(&["x", "y", "z", "w"], "x*y/(z*w^2)");
    assert_eq!(by.get("div"), Some(&1), "{}", p.to_text());
    assert_eq!(by.get("powi"), Some(&1), "{}", p.to_text());
    // Negative terms are subtracted: no negation when one term is positive.
    let (_, by, p) = ops_of(&["x", "y", "z"], "x - y - z");
    assert_eq!(by.get("neg"), None, "{}", p.to_text());
    assert_eq!(by.get("sub"), Some(&2), "{}", p.to_text());
    // An all-negative sum costs a single negation.
    let (_, by, p) = ops_of(&["x", "y", "z"], "-x - y - z");
    assert_eq!(by.get("neg"), Some(&1), "{}", p.to_text());
    // Half-integer powers go through sqrt; 1/2 is a plain sqrt.
    let (total, by, p) = ops_of(&["x"], "x^(1/2)");
    assert_eq!((total, by.get("sqrt")), (1, Some(&1)), "{}", p.to_text());
    let (_, by, p) = ops_of(&["x"], "x^(3/2)");
    assert_eq!((by.get("sqrt"), by.get("powi")), (Some(&1), Some(&1)), "{}", p.to_text());
    // Repeated sub-expressions are computed once.
    let (_, by, p) = ops_of(&["x", "y"], "sin(x*y) + cos(x*y) + sin(x*y)^2");
    assert_eq!((by.get("sin"), by.get("mul")), (Some(&1), Some(&1)), "{}", p.to_text());
    // A coefficient 1/q divides by q.
    let (total, by, p) = ops_of(&["x"], "x/3");
    assert_eq!((total, by.get("div")), (1, Some(&1)), "{}", p.to_text());
    // pi is a constant.
    let (total, _, p) = ops_of(&["x"], "pi*x");
    assert_eq!(total, 1, "{}", p.to_text());
}

#[test]
fn canonical_order_ignores_symbol_creation_order() {
    on_symbolica_thread(canonical_order_ignores_symbol_creation_order_body);
}

fn canonical_order_ignores_symbol_creation_order_body() {
    // The same expression over symbols created in opposite orders (two namespaces) emits the
    // same program text.
    let first = parse!("order_a::alpha*order_a::beta + order_a::alpha - 3*order_a::beta^2");
    let _ = parse!("order_b::beta");
    let _ = parse!("order_b::alpha");
    let second = parse!("order_b::alpha*order_b::beta + order_b::alpha - 3*order_b::beta^2");
    let render = |e: Atom| {
        let d = single(&[], &["alpha", "beta"], e);
        (emit_program(&d).unwrap().to_text(), render_markdown(&d).unwrap())
    };
    assert_eq!(render(first), render(second));
}

fn sample_derivation() -> Derivation {
    let mut d = single(
        &["R", "g"],
        &["theta", "n", "s"],
        parse!("4/3*n*s*cos(theta) + 2/3*g*sin(theta)/R + n^2*sin(theta)*cos(theta)"),
    );
    d.formulas.push(Formula {
        name: "h".to_string(),
        section: "9".to_string(),
        description: "Another formula,\twith a tab (1/s^2).".to_string(),
        expr: parse!("-R*(n*s + n^2*sin(theta))/g + (R/g)^(1/2)"),
    });
    d.checks = vec![
        Check {
            perturbed: Some(carvallo_codegen::Perturbed {
                what: "every `R` of the derived side\tscaled by 9/8".to_string(),
                holds: false,
            }),
            section: "7".to_string(),
            id: "first".to_string(),
            statement: "a statement\nover two lines".to_string(),
            holds: true,
            detail: "difference 0".to_string(),
        },
        Check {
            perturbed: None,
            section: "71".to_string(),
            id: "second".to_string(),
            statement: "a failing one".to_string(),
            holds: false,
            detail: String::new(),
        },
    ];
    d
}

#[test]
fn rendering_is_byte_stable_and_normalised() {
    on_symbolica_thread(rendering_is_byte_stable_and_normalised_body);
}

fn rendering_is_byte_stable_and_normalised_body() {
    let d = sample_derivation();
    let a = (emit_program(&d).unwrap().to_text(), render_markdown(&d).unwrap(), render_checks(&d));
    let b = (emit_program(&d).unwrap().to_text(), render_markdown(&d).unwrap(), render_checks(&d));
    assert_eq!(a, b);
    for text in [&a.0, &a.1, &a.2] {
        assert!(text.ends_with('\n') && !text.ends_with("\n\n"), "one final newline:\n{text}");
        assert!(!text.contains('\r'), "LF only");
        assert!(text.lines().all(|l| !l.ends_with(' ')), "no trailing spaces:\n{text}");
    }
    // The TSV keeps seven columns even with an empty detail or no perturbation (`-`), and
    // flattens tabs and newlines.
    let rows: Vec<&str> = a.2.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(
        rows,
        [
            "7\tfirst\ttrue\ta statement over two lines\tdifference 0\tevery `R` of the derived side scaled by 9/8\tfalse",
            "71\tsecond\tfalse\ta failing one\t\t\t-"
        ]
    );
    insta::with_settings!({ description => "IR of a two-formula sample derivation", omit_expression => true }, {
        insta::assert_snapshot!("emit_sample_ir", a.0);
    });
    insta::with_settings!({ description => "markdown rendering of a two-formula sample derivation", omit_expression => true }, {
        insta::assert_snapshot!("emit_sample_md", a.1);
    });
    insta::with_settings!({ description => "checks TSV of a two-formula sample derivation", omit_expression => true }, {
        insta::assert_snapshot!("emit_sample_checks", a.2);
    });
}

#[test]
fn emitted_program_round_trips_through_text() {
    on_symbolica_thread(emitted_program_round_trips_through_text_body);
}

fn emitted_program_round_trips_through_text_body() {
    let p = emit_program(&sample_derivation()).unwrap();
    let text = p.to_text();
    assert_eq!(Program::parse(&text).unwrap(), p);
    assert!(text.starts_with("# Generated by `cargo xtask regen` from codegen/tests/emit.rs; do not edit by hand.\n# Outputs: f, h.\n"), "{text}");
}

#[test]
fn emit_expr_shares_values_with_an_existing_builder() {
    on_symbolica_thread(emit_expr_shares_values_with_an_existing_builder_body);
}

fn emit_expr_shares_values_with_an_existing_builder_body() {
    let mut b = Builder::new("shared");
    let names: BTreeMap<String, _> = [("x".to_string(), b.input("x"))].into_iter().collect();
    let v1 = emit_expr(&mut b, &names, &parse!("sin(x)^2")).unwrap();
    let v2 = emit_expr(&mut b, &names, &parse!("sin(x)^2")).unwrap();
    assert_eq!(v1, v2);
    assert_eq!(b.finish().insts.len(), 2, "sin and powi, once");
}

/// The optimised lowering (`emit::emit_program_optimized`, symbolica's optimiser) of the
/// hand-written expressions agrees with symbolica's evaluation as the naive lowering does, and
/// with every formula left to the naive rules it is the naive program itself.
#[test]
fn optimised_lowering_matches_symbolica_and_falls_back_to_the_naive_program() {
    on_symbolica_thread(optimised_lowering_body);
}

fn optimised_lowering_body() {
    use carvallo_codegen::emit::{emit_program_optimized, EFFORTS};
    let cases = [
        "-x - y - 1/7",
        "x^5 - 3*x^-3 + x^(1/2) - y^(-1/2) + x^(3/2)*y^(-5/2)",
        "(x + y)^3/(x*y^2*(1 + x^2)) - 1",
        "sqrt(x^2 + y^2) + cos(x*y)^2 + sin(x*y)^2",
        "tan(x)*y - 12345678901234567890123/1000000000000000000000*x",
        "-(x + y)/(3*x^2) - 1/4*x*y^3 + x^2*y^2 - x^3*y",
    ];
    let mut rng = ChaCha8Rng::seed_from_u64(0x0b7);
    for case in cases {
        let expr = parse!(case);
        let d = single(&[], &["x", "y"], expr.clone());
        for effort in EFFORTS {
            let p = emit_program_optimized(&d, effort, &Default::default())
                .unwrap_or_else(|e| panic!("{case}: {e}"));
            for _ in 0..50 {
                let (x, y) = (rng.gen_range(0.5..2.0), rng.gen_range(0.5..2.0));
                let got = p.eval_f64(&[], &[x, y]).expect("the interpreter runs")[0];
                let values = [("x".to_string(), x), ("y".to_string(), y)].into_iter().collect();
                let want = symbolica_eval(&expr, &values);
                assert!(
                    close(got, want),
                    "{case} ({effort}) at ({x}, {y}): {got:e} against {want:e}"
                );
            }
            let all = std::iter::once(0).collect();
            let naive = emit_program_optimized(&d, effort, &all).expect("the naive rules lower it");
            assert_eq!(naive, emit_program(&d).expect("lowers"), "{case}");
        }
    }
}

/// On the unicycle (the largest gain), the optimised program computes the naive program's
/// function: their 256-bit values agree far below f64 rounding at seeded points, with fewer
/// operations.
#[test]
fn optimised_unicycle_is_the_same_function_with_fewer_operations() {
    on_symbolica_thread(optimised_unicycle_body);
}

fn optimised_unicycle_body() {
    use carvallo_codegen::emit::{emit_program_optimized, EFFORTS};
    let d = crate::derived("unicycle");
    let naive = emit_program(d).expect("lowers");
    let opt = emit_program_optimized(d, EFFORTS[1], &Default::default()).expect("lowers");
    assert!(count_ops(&opt).0 * 10 < count_ops(&naive).0 * 6, "{} ops", count_ops(&opt).0);
    let mut rng = ChaCha8Rng::seed_from_u64(0x0b8);
    for _ in 0..5 {
        let params: Vec<f64> = d.params.iter().map(|_| rng.gen_range(0.5..1.5)).collect();
        let inputs: Vec<f64> = d.inputs.iter().map(|_| rng.gen_range(0.5..1.5)).collect();
        let a = carvallo_ir::hp::eval_f64(&naive, &params, &inputs, 256).expect("evaluates");
        let b = carvallo_ir::hp::eval_f64(&opt, &params, &inputs, 256).expect("evaluates");
        for ((x, y), o) in a.iter().zip(&b).zip(&naive.outputs) {
            assert!((x - y).abs() <= 1e-30 * x.abs().max(1.0), "{}: {x:e} against {y:e}", o.name);
        }
    }
}
