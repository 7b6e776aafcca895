//! The figures of `carvallo report --out DIR`, drawn with `plotters` (SVG backend).
//!
//! [`FIGURES`] is the catalogue, in the order of the report: each row names the file, the
//! title (which cites the memoir's figure and n° where it redraws one), the caption and the
//! function that draws it. The functions live in [`memoir`] (the memoir's figures 3, 4, 4 bis,
//! 7, 9, 11 and 13), [`modern`] (eigenvalues, Bode diagrams, stable windows, ground tracks) and
//! [`bicycle`] (the figures of a named bicycle: its geometry, its eigenvalues labelled by mode,
//! Bode diagrams comparing bicycles, its hands-free steady turns), and draw with the engine in
//! [`chart`]. The bicycle figures (files `benchmark_*.svg`) are named after the bicycle drawn:
//! [`Figure::file_for`] and [`Figure::title_for`]. Figures the workspace cannot draw honestly yet are listed in
//! [`MISSING`] with the reason.

mod bicycle;
mod chart;
mod memoir;
mod modern;

use anyhow::Result;
use carvallo::whipple::WhippleParams;

pub use bicycle::{fig_bode, fig_geometry, fig_modes, fig_rider_modes};
#[cfg(test)]
pub(crate) use chart::svg_texts;
pub use modern::{fig_bicycle_eigenvalues, fig_eigenvalue_bands, BAND_SEED};

/// One figure of the report.
pub struct Figure {
    /// File name inside the output directory (`*.svg`).
    pub file: &'static str,
    /// Title, also the chart's caption.
    pub title: &'static str,
    /// One or two sentences saying what the figure shows and where it comes from.
    pub caption: &'static str,
    /// Computes the data and draws the figure for a bicycle and its name (used by the modern
    /// figures only).
    pub draw: fn(&WhippleParams, &str) -> Result<String>,
}

/// The prefix of the files of the figures of the report's bicycle.
const BICYCLE_PREFIX: &str = "benchmark_";

impl Figure {
    /// Its file for the bicycle whose file stem is `stem` ([`crate::args::file_stem_of`]):
    /// `benchmark_eigenvalues.svg` becomes `browser_jason_eigenvalues.svg`; the others keep
    /// theirs.
    pub fn file_for(&self, stem: &str) -> String {
        match self.file.strip_prefix(BICYCLE_PREFIX) {
            Some(rest) => format!("{stem}_{rest}"),
            None => self.file.to_string(),
        }
    }

    /// Its title for the bicycle `name`: `Benchmark bicycle: …` becomes `name: …`.
    pub fn title_for(&self, name: &str) -> String {
        match self.title.strip_prefix("Benchmark bicycle") {
            Some(rest) => format!("{name}{rest}"),
            None => self.title.to_string(),
        }
    }
}

/// A figure of the memoir or of the issue that the workspace does not draw yet, and why.
pub struct Missing {
    /// Which figure.
    pub figure: &'static str,
    /// Why it is not drawn.
    pub reason: &'static str,
}

/// Every figure, in the order of the report. Adding a figure: write its function in
/// [`memoir`] or [`modern`], add a row.
pub const FIGURES: [Figure; 18] = [
        Figure { file: "fig03_hoop_equilibrium.svg", title: "Memoir fig. 3: hoop, reality and stability of the steady states (n° 13–14)", caption: "Plane x = cos θ, y = s² (rates in √(g/R)): the curve (ℰ) where the two roots n of (E) merge, the curve (S1) where those of S are real, and the stability limit (S) through its vertical tangent; points A, B, D, F of n° 14.", draw: |p, _| memoir::fig_3(p) },
        Figure { file: "fig04_hoop_skid.svg", title: "Memoir fig. 4: hoop, skid tendency (n° 15–16)", caption: "Polar diagram (angle θ from the vertical, radius s in √(g/R)): the curves n = const of (E′), the curves D = ±1/2 of (D″), (ℰ) and (S).", draw: |p, _| memoir::fig_4(p) },
        Figure { file: "fig04bis_hoop_walking.svg", title: "Memoir fig. 4 bis: hoop, walking and pivoting (n° 17)", caption: "Polar diagram: (ℰ), (S), the separation (N) between walking and pivoting, and the curves n2 = −0.1, −0.3, −0.5.", draw: |p, _| memoir::fig_4_bis(p) },
        Figure { file: "fig07_unicycle_diagram.svg", title: "Memoir fig. 7: unicycle steady states, h/R = 2.5 (n° 32, 41)", caption: "Polar diagram (angle θ from the vertical, radius s in √(g/R)): (ℰ), the curves n = const of (E), the separation (N) with its asymptote, the branch θ < 16° of the stability limit (S) of n° 41, and the practical limits s = 1 and 20 km/h.", draw: |p, _| memoir::fig_7(p) },
        Figure { file: "fig09_unicycle_first_member.svg", title: "Memoir fig. 9: unicycle, reality condition of S(n²) (n° 41)", caption: "The first member 1/cos θ − (h/R) sin²θ cos θ − √(h/R) sin 2θ from the generated trinomial, against θ, with the memoir's table (n° 41); the derived zeros (marked) are 16.32° and 62.82°, which the memoir reads off its graph as 16°,0 and 62°,7.", draw: |p, _| memoir::fig_9(p) },
        Figure { file: "fig11_bicycle_sigma1_mu1.svg", title: "Memoir fig. 11: bicycle geometry, frame vertical (n° 52)", caption: "The frame's rotation σ1 = σ − σ0 and the front contact's μ1 = μ − μ0 (tan μ0 = tan σ0 cos γ) against the steer γ, in minutes of arc, for the old bicycle of n° 52 (R = 0.38 m, l = 1.10 m, c = 0.08 m, σ0 = 25°): the exact solution of the contact equations (1), (2) by Newton's method (lines) and the memoir's table (points).", draw: |p, _| memoir::fig_11(p) },
        Figure { file: "fig13_bicycle_contact_locus.svg", title: "Memoir fig. 13: locus of the front wheel's contact with the ground (n° 54)", caption: "The front contact M relative to its position M0 at γ = 0, frame vertical, old bicycle of n° 52, for γ from 0° to 90°: the exact solution (line, with γ marked every 20°) and the memoir's table (points); y is counted as in the memoir's table, whose sign is opposite to its printed formula y = −(R sin μ − c) sin γ (see the report, n° 54).", draw: |p, _| memoir::fig_13(p) },
        Figure { file: "benchmark_geometry.svg", title: "Benchmark bicycle: geometry", caption: "Side view of the bicycle (benchmark parameters unless --model is given) from its parameters: the wheels, the steer axis (dashed) tilted back by λ and meeting the ground the trail c ahead of the front contact, a schematic frame and fork, and the mass centres of the rear wheel, rear frame (with the rider when one is added), front frame, front wheel and of the whole (`carvallo plot geometry`).", draw: bicycle::fig_report_geometry },
        Figure { file: "benchmark_eigenvalues.svg", title: "Benchmark bicycle: eigenvalues against speed", caption: "Real parts of the four eigenvalues of the linearised Carvallo–Whipple bicycle (Meijaard et al. 2007 parameters unless --model is given) and the weave's frequency against the forward speed, each labelled by its mode (weave, capsize, caster) as `carvallo modes` labels it, by continuation in speed; the stable range is shaded.", draw: modern::fig_eigenvalues },
        Figure { file: "carvallo_eigenvalues.svg", title: "Carvallo's bicycle without hands (n° 117–122): eigenvalues against speed", caption: "Time eigenvalues sλ (λ the roots of the quartic of n° 119, T = st) of Carvallo's bicycle, exactly linearised through the general model at the constants of n° 117, against v = Rs (R = 0.38 m), the stable range shaded; marked on the axis: the memoir's limits s² = 67.3 and 83.6 (v = 0.38√s²) and the derived ones.", draw: modern::fig_carvallo_eigenvalues },
        Figure { file: "benchmark_hands_free.svg", title: "Benchmark bicycle: hands-free steady turns (n° 97)", caption: "The steady turns of the nonlinear Carvallo–Whipple bicycle (benchmark parameters unless --model is given) that need no steer torque, in the plane of the rear contact's speed and the lean (positive lean; the families are symmetric): each family followed by pseudo-arclength continuation from its branch point on upright running, straight ahead (at the capsize speed) and with the handlebar reversed, solid where the turn is stable with no steer torque, dashed where it is not; folds and branch points marked (`carvallo turn --hands-free`). The memoir's n° 97 finds no turn without hands for its approximate equations.", draw: bicycle::fig_hands_free },
        Figure { file: "benchmark_bode_magnitude.svg", title: "Benchmark bicycle: steer torque to lean, magnitude", caption: "Magnitude of the transfer function from the steer torque Tδ to the lean φ of the linearised bicycle (benchmark parameters unless --model is given) at 2, 4, 5 and 8 m/s, against the angular frequency: numerator (the adjugate of M s² + v C1 s + g K0 + v² K2) and characteristic polynomial both derived symbolically (`carvallo bode`). At 4 m/s, below the weave speed (4.29 m/s), the weave pair 0.41 ± 3.08i lies just right of the imaginary axis: the sharp peak near 3 rad/s; at 5 m/s (stable, −0.78 ± 4.46i) the peak is low and broad.", draw: modern::fig_bode_magnitude },
        Figure { file: "benchmark_bode_phase.svg", title: "Benchmark bicycle: steer torque to lean, phase", caption: "Phase of the same transfer function on the branch continuous in the frequency that lies in (−180°, 180°] as ω → 0⁺ (each zero's and pole's argument on its own branch: a function of ω, not of the grid): through the unstable weave at 4 m/s it rises by about 180° (a right-half-plane pole), through the stable weave at 5 and 8 m/s it falls.", draw: modern::fig_bode_phase },
        Figure { file: "benchmark_balance_assist.svg", title: "Benchmark bicycle: stable speed range against a balance-assist gain", caption: "Closed-loop stable speeds (shaded) of the linearised bicycle (benchmark parameters unless --model is given) with the balance-assist law Tδ = c·dφ/dt, steer torque into the fall in proportion to the roll rate (gain k_steer_roll_rate = −c of u = −Kx), for c from 0 to 50 N m s/rad, by the Hurwitz route on the closed-loop characteristic polynomial derived in v and the gains (`carvallo window --gain`, `carvallo sweep --gain`). The assist lowers the weave speed (4.29 m/s at c = 0) and leaves the capsize speed 6.02 m/s (the roll-rate feedback does not touch a0); the dotted line is the smallest c that makes 2 m/s stable (`carvallo window --assist-down-to 2`: 17.62 N m s/rad for the benchmark).", draw: modern::fig_balance_assist },
        Figure { file: "nonlinear_ground_tracks.svg", title: "Wheel ground tracks from a nonlinear simulation", caption: "Rear and front contact tracks of the nonlinear Carvallo–Whipple bicycle (benchmark parameters unless --model is given), RK4 from upright straight running at 4.6 m/s with an initial lean of 0.05 rad for 6 s; the number of crossings of the two tracks (n° 106), counted from the simulated data, is in the figure's title.", draw: modern::fig_tracks },
        Figure { file: "nonlinear_work_precision.svg", title: "Nonlinear simulation: error against work", caption: "The largest error over the state and over the samples every 0.01 s of the nonlinear Carvallo–Whipple bicycle (benchmark parameters unless --model is given) from upright straight running at 4.6 m/s with a lean of 0.05 rad for 5 s, against the number of right-hand side evaluations: RK4 at steps 0.02 s / 2^k (k = 0 … 6), Dormand–Prince 5(4), DOP853 and Verner's 9(8) at rtol 1e-3 … 1e-12 (atol 1e-3 rtol); the reference is DOP853 at rtol 1e-14 (checked against RK4 at 1e-4 s by `carvallo bench`).", draw: modern::fig_work_precision },
        Figure { file: "benchmark_window_trail.svg", title: "Benchmark bicycle: stable speed range against the trail", caption: "Weave and capsize speeds and the stable range (shaded) as the trail c is varied, the other parameters fixed.", draw: modern::fig_window_trail },
        Figure { file: "benchmark_window_tilt.svg", title: "Benchmark bicycle: stable speed range against the steer axis tilt", caption: "Weave and capsize speeds and the stable range (shaded) as the steer axis tilt λ (head angle 90° − λ) is varied in steps of 0.5°, the other parameters fixed. Below about 9.5° the benchmark has no stable speed; the curves there are the lowest roots of a0 (capsize) and of the Hurwitz determinant H3 (weave), which bound no stable range (a0 has no positive root at 1.5°, hence the gap).", draw: modern::fig_window_tilt },
];

/// Figures not drawn, with the reason (listed in `report.md`); every figure the issues name is
/// drawn now.
pub const MISSING: [Missing; 0] = [];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn figure_files_are_distinct_svgs_and_the_missing_ones_are_named() {
        let figs = &FIGURES;
        let mut files: Vec<&str> = figs.iter().map(|f| f.file).collect();
        files.sort_unstable();
        files.dedup();
        assert_eq!(files.len(), figs.len(), "two figures share a file name");
        assert!(files.iter().all(|f| f.ends_with(".svg") && !f.contains('/')));
        assert_eq!((figs.len(), MISSING.len()), (18, 0));
        for drawn in [
            "carvallo_eigenvalues.svg",
            "benchmark_balance_assist.svg",
            "nonlinear_ground_tracks.svg",
            "fig11_bicycle_sigma1_mu1.svg",
            "fig13_bicycle_contact_locus.svg",
            "benchmark_hands_free.svg",
        ] {
            assert!(files.contains(&drawn), "{drawn} not drawn");
        }
    }

    #[test]
    fn the_hands_free_figure_draws_both_families_and_the_stable_section() {
        let fig = FIGURES.iter().find(|f| f.file == "benchmark_hands_free.svg").unwrap();
        let svg = (fig.draw)(&WhippleParams::benchmark(), "Benchmark bicycle").expect("drawn");
        let texts = svg_texts(&svg);
        // The branch points: the capsize speed and the reversed run's (`turn --hands-free`).
        for t in [
            "6.024 m/s",
            "7.901 m/s",
            "handlebar forward, unstable",
            "handlebar reversed, unstable",
            "handlebar reversed, stable",
        ] {
            assert!(texts.iter().any(|x| x == t), "{t} not in {texts:?}");
        }
        // The forward family is stable nowhere; six folds are marked (one on the forward
        // family, three on the reversed one after merging the two at 4.58 m/s, two on the
        // first isolated one); the isolated families have no branch point.
        assert!(!texts.iter().any(|x| x == "handlebar forward, stable"), "{texts:?}");
        assert_eq!(texts.iter().filter(|x| *x == "fold").count(), 6, "{texts:?}");
        for t in ["isolated 1, stable", "isolated 1, unstable", "isolated 2, unstable"] {
            assert!(texts.iter().any(|x| x == t), "{t} not in {texts:?}");
        }
        assert_eq!(texts.iter().filter(|x| x.ends_with(" m/s")).count(), 2, "{texts:?}");
    }

    #[test]
    fn the_bicycle_figures_take_the_bicycles_name() {
        let eig = FIGURES.iter().find(|f| f.file == "benchmark_eigenvalues.svg").unwrap();
        assert_eq!(eig.file_for("browser_jason"), "browser_jason_eigenvalues.svg");
        assert_eq!(eig.title_for("Browser + Jason"), "Browser + Jason: eigenvalues against speed");
        assert_eq!(eig.title_for("Benchmark bicycle"), eig.title);
        let fig3 = &FIGURES[0];
        assert_eq!(
            (fig3.file_for("x"), fig3.title_for("x")),
            (fig3.file.into(), fig3.title.into())
        );
    }
}
