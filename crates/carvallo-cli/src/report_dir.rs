//! `carvallo report --out DIR [--model benchmark|FILE.toml|FILE.txt]`: writes `DIR/report.md`
//! (the concordance grouped by the memoir's part, chapter and §, and the errata), the same as
//! one self-contained page `DIR/report.html` ([`crate::report_html`]) and the SVG figures of
//! [`crate::figures`]. A parameter file with stated uncertainties (BicycleParameters' text
//! format) adds a section on their propagation to the weave and capsize speeds (first order
//! and Monte Carlo) and the eigenvalue figure with uncertainty bands.
//!
//! [`write_bicycle_report`] writes the report of one bicycle alone (`report --out DIR --model
//! FILE [--rider FILE]`): the file and rider read, the parameters, the stable speed range, the
//! eigenvalues against speed and, with stated uncertainties, their propagation and the bands
//! figure; none of the memoir's chapters is computed.
//!
//! Nothing is written unless everything succeeds: the directory is checked first (its parent
//! must exist and be writable; an existing `DIR` must be empty or a report directory written
//! before, marked by the file [`MARKER`], so that a mistyped `--out .` can never replace
//! unrelated files), the report and figures are computed in memory, written into a locked
//! temporary sibling directory, and that directory replaces `DIR` atomically where the file
//! system allows ([`crate::staging`]). A progress bar is drawn on standard error only when it is
//! a terminal.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use carvallo::parameter_text::UncertainParams;
use carvallo::whipple::{Whipple, PARAM_NAMES};
use carvallo::whipple_uncertainty::{mean_std, monte_carlo, speed_gradients};

use crate::figures;
use crate::report_html::{escape, escape_with_code, render_html, HtmlFigure};
use crate::staging::Staging;

/// The file that marks a directory written by `carvallo report --out`.
pub const MARKER: &str = ".carvallo-report";

/// A bad output directory or parameter file (exit code 2), found before anything is written.
#[derive(Debug, PartialEq, Eq)]
pub struct BadInput(pub String);

impl std::fmt::Display for BadInput {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for BadInput {}

/// Checks that `dir` can receive a report; returns its parent directory.
pub fn check_out_dir(dir: &Path) -> Result<PathBuf, BadInput> {
    let shown = dir.display();
    if dir.file_name().is_none_or(|n| n == "." || n == "..") {
        return Err(BadInput(format!("invalid output directory `{shown}`: give a directory name")));
    }
    let parent = match dir.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if !parent.is_dir() {
        return Err(BadInput(format!(
            "invalid output directory `{shown}`: its parent `{}` is not an existing directory",
            parent.display()
        )));
    }
    if dir.exists() {
        if !dir.is_dir() {
            return Err(BadInput(format!(
                "invalid output directory `{shown}`: it is not a directory"
            )));
        }
        let empty = std::fs::read_dir(dir).map(|mut d| d.next().is_none()).unwrap_or(false);
        if !empty && !dir.join(MARKER).is_file() {
            return Err(BadInput(format!(
                "refusing to replace `{shown}`: it is not empty and was not written by `carvallo report --out`"
            )));
        }
    }
    Ok(parent)
}

/// The progress of `report --out`: an `indicatif` bar `[####    ] k/n what` on standard error,
/// drawn only when it is a terminal (indicatif hides it otherwise); the line is ended when the
/// work stops, also early by an error.
struct Progress {
    bar: indicatif::ProgressBar,
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.finish();
    }
}

impl Progress {
    fn new(total: usize) -> Progress {
        let bar = indicatif::ProgressBar::with_draw_target(
            Some(total as u64),
            indicatif::ProgressDrawTarget::stderr(),
        );
        let style = indicatif::ProgressStyle::with_template("[{bar:30}] {pos}/{len} {msg}")
            .map(|s| s.progress_chars("## "))
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar());
        bar.set_style(style);
        Progress { bar }
    }

    /// Shows `what` as the work in progress, with the steps done so far.
    fn start(&self, what: &str) {
        self.bar.set_message(what.to_string());
    }

    fn done(&mut self) {
        self.bar.inc(1);
    }

    fn finish(&mut self) {
        if !self.bar.is_finished() {
            self.bar.abandon();
        }
    }
}

/// The Markdown section listing the figures (as images) and the missing ones, the bicycle
/// figures named after the bicycle `name` (file stem `stem`).
pub fn figures_section(figs: &[figures::Figure], name: &str, stem: &str) -> String {
    let mut s = String::from("## Figures\n\n");
    for f in figs {
        let (title, file) = (f.title_for(name), f.file_for(stem));
        s.push_str(&format!("### {title}\n\n![{title}]({file})\n\n{}\n\n", f.caption));
    }
    s.push_str("### Figures not drawn yet\n\n");
    if figures::MISSING.is_empty() {
        s.push_str("None: every figure listed in the report's brief is drawn above.\n");
    }
    for m in &figures::MISSING {
        s.push_str(&format!("- {}: {}.\n", m.figure, m.reason));
    }
    s
}

/// The Monte Carlo sample size of the report's uncertainty section.
pub const UNCERTAINTY_SAMPLES: usize = 10_000;

/// The Monte Carlo sample size of the bands figure (eigenvalues at 101 speeds per sample).
pub const BAND_SAMPLES: usize = 2_000;

/// The report's uncertainty section: the stated standard deviations of `u` propagated to the
/// weave and capsize speeds, first order (exact derivatives) and Monte Carlo
/// ([`UNCERTAINTY_SAMPLES`] seeded samples); as Markdown and as HTML.
pub fn uncertainty_section(u: &UncertainParams, model: &str) -> (String, String) {
    let g = speed_gradients(&u.params);
    let mc = monte_carlo(u, UNCERTAINTY_SAMPLES, figures::BAND_SEED);
    let intro = format!(
        "The parameter file `{model}` states standard deviations for {} of the 26 parameters. \
         They are propagated, as independent normal errors, to the weave and capsize speeds: at \
         first order, with the speeds' derivatives exact to rounding (dual numbers through the \
         generated `whipple.ir` and the implicit function theorem on the Hurwitz function whose \
         root the speed is), and by Monte Carlo ({UNCERTAINTY_SAMPLES} samples, seed {}, each \
         window by the closed-form Hurwitz route; {} samples break a triangle inequality of the \
         moments of inertia and are kept).",
        u.sigma.iter().filter(|s| **s > 0.0).count(),
        figures::BAND_SEED,
        mc.invalid
    );
    let mut rows = Vec::new();
    for (name, first, sample) in [
        ("weave speed", g.weave.as_ref(), &mc.weave),
        ("capsize speed", g.capsize.as_ref(), &mc.capsize),
    ] {
        let (mean, std, n) = mean_std(sample);
        let mut sorted: Vec<f64> = sample.iter().copied().filter(|x| x.is_finite()).collect();
        sorted.sort_by(f64::total_cmp);
        let q = |p: f64| sorted.get(((sorted.len() as f64 - 1.0) * p).round() as usize).copied();
        let cells = match first {
            Some(f) => {
                let mut top: Vec<(usize, f64)> =
                    f.grad.iter().zip(&u.sigma).map(|(d, s)| (d * s).abs()).enumerate().collect();
                top.sort_by(|a, b| b.1.total_cmp(&a.1));
                let top: Vec<String> = top
                    .iter()
                    .take(3)
                    .filter(|(_, c)| *c > 0.0)
                    .map(|(k, c)| format!("{} ({:.4})", PARAM_NAMES[*k], c))
                    .collect();
                [format!("{:.4}", f.speed), format!("{:.4}", f.std(&u.sigma)), top.join(", ")]
            }
            None => ["none".into(), "–".into(), "–".into()],
        };
        let interval = match (q(0.025), q(0.975)) {
            (Some(a), Some(b)) => format!("{a:.4} – {b:.4}"),
            _ => "–".to_string(),
        };
        rows.push([
            name.to_string(),
            cells[0].clone(),
            cells[1].clone(),
            format!("{mean:.4}"),
            format!("{std:.4}"),
            interval,
            format!("{n}"),
            cells[2].clone(),
        ]);
    }
    let header = [
        "speed",
        "nominal (m/s)",
        "first-order std (m/s)",
        "Monte Carlo mean",
        "Monte Carlo std",
        "95 % of the samples",
        "samples with it",
        "largest first-order contributions (∂v/∂p)·σ",
    ];
    let mut md = format!(
        "## Uncertainty of the bicycle\n\n{intro}\n\n| {} |\n|{}\n",
        header.join(" | "),
        "---|".repeat(header.len())
    );
    let mut html = format!(
        "<h2 id=\"uncertainty\">Uncertainty of the bicycle</h2>\n<p>{}</p>\n<table>\n<thead><tr>{}</tr></thead>\n<tbody>\n",
        escape_with_code(&intro),
        header.iter().map(|h| format!("<th>{}</th>", escape(h))).collect::<String>()
    );
    for r in &rows {
        md.push_str(&format!("| {} |\n", r.join(" | ")));
        html.push_str(&format!(
            "<tr>{}</tr>\n",
            r.iter().map(|c| format!("<td>{}</td>", escape(c))).collect::<String>()
        ));
    }
    md.push('\n');
    html.push_str("</tbody>\n</table>\n");
    (md, html)
}

/// The file name of the uncertainty bands figure.
pub const BANDS_FILE: &str = "eigenvalue_bands.svg";
const BANDS_TITLE: &str = "The bicycle of the parameter file: eigenvalues with uncertainty bands";
const BANDS_CAPTION: &str = "Real parts of the four eigenvalues against speed (points: nominal parameters) and, for each, the band between the 2.5 % and 97.5 % quantiles over 2 000 Monte Carlo samples of the stated uncertainties (seeded); the nominal stable range shaded.";

/// Computes the report and the figures for the bicycle `params` (read from `model`, named
/// `name` in the bicycle figures' titles and files: [`figures::Figure::title_for`] and
/// [`figures::Figure::file_for`]) and writes them to `dir` (see the module docs). Returns the
/// files written, relative to `dir`.
pub fn write_report(
    dir: &Path,
    params: &UncertainParams,
    model: &str,
    name: &str,
) -> Result<Vec<String>> {
    let stem = crate::args::file_stem_of(name);
    let staging = Staging::new(dir, &check_out_dir(dir)?)?;
    let figs = &figures::FIGURES;
    let banded = params.has_uncertainty();
    let mut progress = Progress::new(figs.len() + 2 + 2 * usize::from(banded));
    progress.start("concordance");
    let entries = carvallo_report::all_entries();
    progress.done();
    let mut files: Vec<(String, String)> = Vec::new();
    for f in figs {
        let file = f.file_for(&stem);
        progress.start(&file);
        let svg = (f.draw)(&params.params, name).with_context(|| format!("cannot draw {file}"))?;
        files.push((file, svg));
        progress.done();
    }
    let (mut extra_md, mut extra_html) = (String::new(), String::new());
    if banded {
        progress.start("uncertainty");
        (extra_md, extra_html) = uncertainty_section(params, model);
        progress.done();
        progress.start(BANDS_FILE);
        let svg = figures::fig_eigenvalue_bands(params, BAND_SAMPLES)
            .with_context(|| format!("cannot draw {BANDS_FILE}"))?;
        extra_md.push_str(&format!("![{BANDS_TITLE}]({BANDS_FILE})\n\n*{BANDS_CAPTION}*\n\n"));
        files.push((BANDS_FILE.to_string(), svg));
        progress.done();
    }
    progress.start("writing");
    let mut figures_md = figures_section(figs, name, &stem);
    if !extra_md.is_empty() {
        figures_md = format!("{extra_md}{figures_md}");
    }
    let claims = carvallo_report::all_claims();
    let assertions = carvallo_report::all_assertions();
    let mut md = carvallo_report::render_markdown(&entries, &claims, &assertions, &figures_md);
    let titles: Vec<String> = files
        .iter()
        .map(|(file, _)| match figs.iter().find(|f| f.file_for(&stem) == *file) {
            Some(f) => f.title_for(name),
            None => BANDS_TITLE.to_string(),
        })
        .collect();
    let html_figs: Vec<HtmlFigure<'_>> = files
        .iter()
        .zip(&titles)
        .map(|((file, svg), title)| {
            let caption = match figs.iter().find(|f| f.file_for(&stem) == *file) {
                Some(f) => f.caption,
                None => BANDS_CAPTION,
            };
            HtmlFigure { file, title, caption, svg }
        })
        .collect();
    let mut html = render_html(&entries, &claims, &assertions, &html_figs, &extra_html);
    if model != "benchmark" {
        let note = format!("The bicycle figures use the parameter file `{model}`.");
        md.push_str(&format!("{note}\n"));
        html = html.replace("</body>", &format!("<p>{}</p>\n</body>", escape_with_code(&note)));
    }
    files.insert(0, ("report.md".to_string(), md));
    files.insert(1, ("report.html".to_string(), html));
    let result = commit(staging, &mut files);
    progress.done();
    progress.start(if result.is_ok() { "written" } else { "failed" });
    progress.finish();
    result?;
    Ok(files.into_iter().map(|(n, _)| n).collect())
}

/// Writes `files` and the [`MARKER`] into the temporary directory of `staging` and puts it in
/// place of `DIR` ([`Staging::commit`]); on failure nothing is left.
fn commit(staging: Staging, files: &mut Vec<(String, String)>) -> Result<()> {
    files.push((MARKER.to_string(), "written by `carvallo report --out`\n".to_string()));
    staging.commit(files)
}

/// The file name of the eigenvalue figure of [`write_bicycle_report`], after the bicycle's file
/// stem (`browser_jason_eigenvalues.svg`).
pub fn eigenvalues_file(stem: &str) -> String {
    format!("{stem}_eigenvalues.svg")
}

/// The file name of the geometry figure of [`write_bicycle_report`] (`browser_geometry.svg`).
pub fn geometry_file(stem: &str) -> String {
    format!("{stem}_geometry.svg")
}

/// A speed for the report's text: round-trip digits, `none` when absent.
fn speed_text(v: Option<f64>) -> String {
    v.map_or("none".to_string(), |x| format!("{x:?} m/s"))
}

/// The report of the bicycle `params` read from `model` (with the rider file `rider` added to
/// its rear frame, and the reader's `warnings`), drawn as `view` (the bicycle and the rider
/// apart) and named after them ([`crate::args::bicycle_name`]), written to `dir` as
/// `report.md`, `report.html` (self-contained), the geometry figure [`geometry_file`], the
/// eigenvalue figure [`eigenvalues_file`] and, with stated uncertainties, [`BANDS_FILE`]: the
/// file and rider read, the parameters and their standard deviations, the stable speed range
/// (closed-form Hurwitz route, as `carvallo window`), the geometry, the eigenvalues against
/// speed labelled by mode and the uncertainty section of [`uncertainty_section`]. The memoir's
/// chapters are not computed. Nothing is written unless everything succeeds, as for
/// [`write_report`]. Returns the files written, relative to `dir`.
pub fn write_bicycle_report(
    dir: &Path,
    params: &UncertainParams,
    model: &str,
    rider: Option<&str>,
    view: &carvallo::whipple::drawing::SideView,
    warnings: &[String],
) -> Result<Vec<String>> {
    let name = crate::args::bicycle_name(model, rider);
    let stem = crate::args::file_stem_of(&name);
    let (eig_file, geo_file) = (eigenvalues_file(&stem), geometry_file(&stem));
    let staging = Staging::new(dir, &check_out_dir(dir)?)?;
    let window = Whipple::new(params.params.clone()).stability_window();
    let source = match rider {
        Some(r) => format!(
            "Parameters read from `{model}`, with the rider of `{r}` added to the rear frame \
             (joint mass and mass centre, inertia by the parallel-axis theorem)."
        ),
        None => format!("Parameters read from `{model}`."),
    };
    let mut notes = vec![source];
    for w in warnings {
        notes.push(format!("Warning: {w}."));
    }
    notes.push(
        "Written by `carvallo report --out DIR --model FILE`; the memoir's chapters are in \
         `carvallo report --out DIR` (or with `--memoir`)."
            .to_string(),
    );
    let stable: Vec<String> = window
        .stable
        .iter()
        .map(|(a, b)| {
            if b.is_finite() {
                format!("from {a:?} to {b:?} m/s")
            } else {
                format!("above {a:?} m/s")
            }
        })
        .collect();
    let window_lines = [
        format!("Weave speed: {}.", speed_text(window.weave_speed)),
        format!("Capsize speed: {}.", speed_text(window.capsize_speed)),
        if stable.is_empty() {
            "No stable speed.".to_string()
        } else {
            format!("Stable {}.", stable.join(", "))
        },
    ];
    let mut files: Vec<(String, String)> = Vec::new();
    let v_max = window.capsize_speed.map_or(10.0, |c| (1.25 * c).clamp(10.0, 30.0).ceil());
    let title = format!("{name}: eigenvalues against speed");
    let svg = figures::fig_modes(&params.params, &name, v_max)
        .with_context(|| format!("cannot draw {eig_file}"))?;
    files.push((eig_file.clone(), svg));
    let geo_title = format!("{name}: geometry");
    let geo_svg = figures::fig_geometry(&[(name.clone(), view.clone())])
        .with_context(|| format!("cannot draw {geo_file}"))?;
    let caption = "Real parts of the four eigenvalues of the linearised Carvallo–Whipple bicycle \
                   and the weave's frequency against the forward speed, each labelled by its \
                   mode (weave, capsize, caster) by continuation in speed; the stable range is \
                   shaded.";
    let geo_caption = "Side view from the parameters: the wheels, the steer axis (dashed) and \
                       the trail, a schematic frame and fork, the mass centres of each body (the \
                       rider's apart when a rider file is given) and of the whole.";
    let (mut unc_md, mut unc_html) = (String::new(), String::new());
    if params.has_uncertainty() {
        (unc_md, unc_html) = uncertainty_section(params, model);
        let svg = figures::fig_eigenvalue_bands(params, BAND_SAMPLES)
            .with_context(|| format!("cannot draw {BANDS_FILE}"))?;
        unc_md.push_str(&format!("![{BANDS_TITLE}]({BANDS_FILE})\n\n*{BANDS_CAPTION}*\n\n"));
        unc_html.push_str(&format!(
            "<figure id=\"{BANDS_FILE}\">\n{svg}\n<figcaption>{}</figcaption>\n</figure>\n",
            escape(BANDS_CAPTION)
        ));
        files.push((BANDS_FILE.to_string(), svg));
    }
    let rows: Vec<(String, String, String)> = PARAM_NAMES
        .iter()
        .enumerate()
        .map(|(k, n)| {
            let s = params.sigma[k];
            let sigma = if s > 0.0 { format!("{s:?}") } else { "–".to_string() };
            (n.to_string(), format!("{:?}", params.params.values()[k]), sigma)
        })
        .collect();
    let heading = format!(
        "Bicycle report: `{model}`{}",
        rider.map_or(String::new(), |r| format!(" with the rider `{r}`"))
    );
    let mut md = format!("# {heading}\n\n{}\n\n## Stable speed range\n\n", notes.join(" "));
    md.push_str(&window_lines.join(" "));
    md.push_str(&format!(
        "\n\n## Geometry\n\n![{geo_title}]({geo_file})\n\n*{geo_caption}*\n\n\
         ## Eigenvalues against speed\n\n![{title}]({eig_file})\n\n*{caption}*\n\n"
    ));
    md.push_str(&unc_md);
    md.push_str("## Parameters\n\n| parameter | value | standard deviation |\n|---|---|---|\n");
    for (n, v, s) in &rows {
        md.push_str(&format!("| {n} | {v} | {s} |\n"));
    }
    let eig_svg = &files[0].1;
    let mut html = format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{}</title>\n<style>{}</style>\n</head>\n<body>\n<h1>{}</h1>\n<p id=\"source\">{}</p>\n\
         <h2 id=\"window\">Stable speed range</h2>\n<p>{}</p>\n\
         <h2 id=\"geometry\">Geometry</h2>\n\
         <figure id=\"{geo_file}\">\n{geo_svg}\n<figcaption>{}</figcaption>\n</figure>\n\
         <h2 id=\"eigenvalues\">Eigenvalues against speed</h2>\n\
         <figure id=\"{eig_file}\">\n{eig_svg}\n<figcaption>{}</figcaption>\n</figure>\n{unc_html}",
        escape(&heading.replace('`', "")),
        crate::report_html::STYLE,
        escape_with_code(&heading),
        escape_with_code(&notes.join(" ")),
        escape(&window_lines.join(" ")),
        escape(geo_caption),
        escape(caption),
    );
    html.push_str("<h2 id=\"parameters\">Parameters</h2>\n<table>\n<thead><tr><th>parameter</th><th>value</th><th>standard deviation</th></tr></thead>\n<tbody>\n");
    for (n, v, s) in &rows {
        html.push_str(&format!(
            "<tr><td>{}</td><td>{}</td><td>{}</td></tr>\n",
            escape(n),
            escape(v),
            escape(s)
        ));
    }
    html.push_str("</tbody>\n</table>\n</body>\n</html>\n");
    files.insert(0, ("report.md".to_string(), md));
    files.insert(1, ("report.html".to_string(), html));
    files.insert(2, (geo_file, geo_svg));
    commit(staging, &mut files)?;
    Ok(files.into_iter().map(|(n, _)| n).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_figure_of_the_catalogue_is_written_and_linked() {
        let dir = std::env::temp_dir().join(format!("carvallo-report-dir-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let params = UncertainParams::exact(carvallo::whipple::WhippleParams::benchmark());
        let files =
            write_report(&dir, &params, "benchmark", "Benchmark bicycle").expect("report written");
        let md = std::fs::read_to_string(dir.join("report.md")).expect("report.md");
        for fig in &figures::FIGURES {
            assert!(files.iter().any(|f| f == fig.file), "{} not in {files:?}", fig.file);
            let svg = std::fs::read_to_string(dir.join(fig.file)).expect(fig.file);
            assert!(svg.starts_with("<svg") && svg.contains("<text"), "{}", fig.file);
            assert!(
                md.contains(&format!("({})", fig.file)),
                "report.md does not link {}",
                fig.file
            );
        }
        std::fs::remove_dir_all(&dir).expect("scratch directory removed");
    }

    #[test]
    fn the_whole_report_of_another_bicycle_names_its_figures_after_it() {
        let dir =
            std::env::temp_dir().join(format!("carvallo-report-named-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let data = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/bicycleparameters");
        let bike = format!("{data}/bicycles/Browser/Parameters/BrowserBenchmark.txt");
        let rider = format!("{data}/riders/Jason/Parameters/JasonBrowserBenchmark.txt");
        let data = crate::args::DataOptions { rider: Some(rider.clone()), ..Default::default() };
        let (params, _) = crate::args::uncertain_bicycle(&bike, &data).expect("read");
        let name = crate::args::bicycle_name(&bike, Some(&rider));
        let files = write_report(&dir, &params, &bike, &name).expect("report written");
        assert!(!files.iter().any(|f| f.starts_with("benchmark_")), "{files:?}");
        for f in [
            "browser_jason_eigenvalues.svg",
            "browser_jason_geometry.svg",
            "browser_jason_bode_phase.svg",
        ] {
            assert!(files.iter().any(|x| x == f), "{f} not in {files:?}");
        }
        let svg = std::fs::read_to_string(dir.join("browser_jason_eigenvalues.svg")).unwrap();
        let texts = figures::svg_texts(&svg);
        assert!(
            texts.iter().any(|t| t == "Browser + Jason: eigenvalues against speed"),
            "{texts:?}"
        );
        let md = std::fs::read_to_string(dir.join("report.md")).unwrap();
        assert!(md.contains("### Browser + Jason: geometry\n\n![Browser + Jason: geometry](browser_jason_geometry.svg)"));
        std::fs::remove_dir_all(&dir).expect("scratch directory removed");
    }
}
