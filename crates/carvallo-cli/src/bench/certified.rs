//! Table 4 of `carvallo bench`: the compensated classification of
//! [`carvallo::whipple::certified`] near the weave speed against the plain `f64` sign of $H_3$.

use std::hint::black_box;

use carvallo::numerics::rng::SplitMix64;
use carvallo::whipple::{Whipple, WhippleParams};

use super::measure::{matrices_of, random_design, time_ns, Config, Row};

/// Table 4: near the weave speed of `designs` bicycles.
pub(super) fn certified_rows(cfg: &Config, rows: &mut Vec<Row>) {
    use carvallo::whipple::certified::{classify, hurwitz_f64, Certified};
    let mut rng = SplitMix64(8);
    let mut designs = vec![WhippleParams::benchmark()];
    designs.extend((1..cfg.designs.max(1)).map(|_| random_design(&mut rng)));
    let offsets = [1e-4, 1e-8, 1e-12, 1e-14, 0.0, -1e-14, -1e-12, -1e-8, -1e-4];
    let (mut stable, mut unstable, mut indet, mut f64_wrong, mut n) = (0, 0, 0, 0, 0);
    let mut f64_flips = 0;
    let mut example = (0.0, 0.0);
    for d in &designs {
        let w = Whipple::new(d.clone());
        let (m, g) = matrices_of(&w);
        let Some(vw) = w.stability_window().weave_speed else { continue };
        for off in offsets {
            let v = vw * (1.0 + off);
            n += 1;
            let c = classify(&m, g, v, 0.0);
            let h = hurwitz_f64(&m, g, v);
            let full = carvallo::whipple::certified::hurwitz_bounded(&m, g, v, 0.0).1;
            if full.sign().is_some_and(|s| s != (h > 0.0)) {
                f64_wrong += 1;
            }
            if off == 0.0 && example.1 == 0.0 {
                example = (full.value.to_f64(), full.err);
            }
            if (off > 0.0) != (h > 0.0) && off != 0.0 {
                f64_flips += 1;
            }
            match c {
                Certified::Stable => stable += 1,
                Certified::Unstable => unstable += 1,
                Certified::Indeterminate => indet += 1,
            }
        }
    }
    let (m, g) = matrices_of(&Whipple::new(WhippleParams::benchmark()));
    let t = time_ns(cfg.min_time, || classify(black_box(&m), g, 5.0, 0.0));
    let t64 = time_ns(cfg.min_time, || hurwitz_f64(black_box(&m), g, 5.0));
    rows.push(Row {
        section: "certified",
        name: format!("H3 near the weave speed, {n} speeds"),
        method: "double-double with error bound".into(),
        ops: None,
        ns: Some(t),
        max_rel_err: None,
        note: format!(
            "{stable} stable, {unstable} unstable, {indet} indeterminate; benchmark at its weave \
             speed: H3 = {:.3e} +- {:.1e}",
            example.0, example.1
        ),
    });
    rows.push(Row {
        section: "certified",
        name: format!("H3 near the weave speed, {n} speeds"),
        method: "plain f64".into(),
        ops: None,
        ns: Some(t64),
        max_rel_err: None,
        note: format!(
            "f64 H3 has the wrong sign (against a certified one) {f64_wrong} times; its sign \
             differs from the side of the computed weave speed {f64_flips} times"
        ),
    });
}
