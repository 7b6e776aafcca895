//! A scene over the fixture, compiled as its own crate, checked against hand-computed values.

carvallo_macros::scene! {
    /// `R` and `g` fixed, `trig` and `root` only.
    pub mod window {
        model: demo,
        path: "../../fixtures/demo.ir",
        fixed: { R: 0.5, g: 9.81 },
        outputs: [trig, root],
    }
}

fn main() {
    // 40-digit values at x = 0.5, y = 2, z = 4 (mpmath); relative tolerance 1e-14.
    let want_trig = -0.9790265950742909202489940791258527733884_f64;
    let want_root = -0.1957557470420728158704578879227758939679_f64;
    let out = window::eval(&window::Args {
        x: 0.5,
        y: 2.0,
        z: 4.0,
    });
    assert!(
        (out.trig - want_trig).abs() <= 1e-14 * want_trig.abs(),
        "trig {}",
        out.trig
    );
    assert!(
        (out.root - want_root).abs() <= 1e-14 * want_root.abs(),
        "root {}",
        out.root
    );
    assert_eq!(window::INPUTS, ["x", "y", "z"]);
    assert!(window::PARAMS.is_empty());
    // trig: 7 operations; root: sqrt g folded, z^-2, product and negation left.
    assert_eq!(window::OP_COUNT, 10);
    let [trig, root] = window::eval_array(&[0.5, 2.0, 4.0]);
    assert_eq!((trig, root), (out.trig, out.root));
}
