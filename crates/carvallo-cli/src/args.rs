//! Argument helpers shared by the subcommands: the value parsers clap calls (numbers that must
//! parse and be finite), the options `--rider FILE` and `--strict`, the bicycle that
//! `--model benchmark|FILE` names, and the bounded reading of input files ([`read_text`]).

use carvallo::parameter_text::{add_rider, Loaded, Rider, UncertainParams};
use carvallo::whipple::lean_rider::{LeanRider, LeanRiderParams};
use carvallo::whipple::WhippleParams;

/// A finite number, for clap's `value_parser` (the error names the value with its option).
pub fn finite(v: &str) -> Result<f64, String> {
    let x: f64 = v.parse().map_err(|_| "not a number".to_string())?;
    if !x.is_finite() {
        return Err("must be finite".into());
    }
    Ok(x)
}

/// The numerically valid range of a number: where its computation neither overflows nor loses
/// all its precision (not what seems physically usual: studies go far from the benchmark).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    /// The least value.
    pub lo: f64,
    /// The greatest value.
    pub hi: f64,
    /// Why the range ends there, for the error.
    pub why: &'static str,
}

/// Speeds of the bicycle [m/s]: beyond $10^6$ the gravity terms $g K_0$ fall within a few digits
/// of the rounding of $v^2 K_2$ (and $v^2$ overflows at $10^{154}$).
pub const SPEED: Range = Range {
    lo: -1e6,
    hi: 1e6,
    why: "beyond it gravity is lost in the rounding of the speed terms",
};
/// Angles in radians, and in degrees: beyond $10^6$ an angle keeps fewer than ten digits of its
/// sine (and none past $10^{16}$).
pub const ANGLE: Range =
    Range { lo: -1e6, hi: 1e6, why: "beyond it the angle's sine loses its digits" };
/// Angular rates (rad/s) of the hoop and the unicycle: their squares times the lengths stay far
/// from overflow and the energy keeps the gravity term.
pub const RATE: Range =
    Range { lo: -1e6, hi: 1e6, why: "beyond it gravity is lost in the rounding of the rate terms" };
/// Lengths (m): positive, so that products of up to six of them with the masses stay normal
/// numbers.
pub const LENGTH: Range =
    Range { lo: 1e-6, hi: 1e6, why: "the equations' determinants must stay normal numbers" };
/// Masses (kg): positive, as [`LENGTH`].
pub const MASS: Range =
    Range { lo: 1e-30, hi: 1e30, why: "the equations' determinants must stay normal numbers" };
/// Moments of inertia (kg m²), zero allowed.
pub const INERTIA: Range =
    Range { lo: 0.0, hi: 1e42, why: "the equations' determinants must stay normal numbers" };
/// Products of inertia (kg m²), of either sign.
pub const PRODUCT: Range =
    Range { lo: -1e42, hi: 1e42, why: "the equations' determinants must stay normal numbers" };
/// A mass in kg that may be zero (a wheel's).
pub const MASS_OR_ZERO: Range = Range { lo: 0.0, ..MASS };
/// The acceleration of gravity [m/s²]: positive (the hoop and the unicycle stand on it).
pub const GRAVITY: Range = Range {
    lo: 1e-6,
    hi: 1e6,
    why: "gravity is positive, and beyond it the rates are lost in its rounding",
};
/// Gains of the state feedback: beyond $10^{12}$ the closed-loop matrix loses the bicycle's own
/// terms in its rounding.
pub const GAIN: Range = Range {
    lo: -1e12,
    hi: 1e12,
    why: "beyond it the bicycle's own terms are lost in the rounding of the feedback",
};
/// Torques (N m) of a driven run: as [`GAIN`].
pub const TORQUE: Range = Range {
    lo: -1e12,
    hi: 1e12,
    why: "beyond it the bicycle's own terms are lost in the rounding of the torque",
};
/// Angular frequencies (rad/s) of `bode`: the transfer function's powers of ω stay normal.
pub const FREQUENCY: Range =
    Range { lo: 1e-12, hi: 1e12, why: "the transfer function's powers of omega must stay normal" };

impl Range {
    /// `x` if it lies in the range, or the error naming the range.
    pub fn check(&self, x: f64) -> Result<f64, String> {
        if x >= self.lo && x <= self.hi {
            Ok(x)
        } else {
            Err(self.message())
        }
    }

    /// The error of a value outside.
    pub fn message(&self) -> String {
        format!("must lie within [{:e}, {:e}] ({})", self.lo, self.hi, self.why)
    }

    /// The value parser of clap: a finite number within the range.
    pub fn parser(self) -> impl Fn(&str) -> Result<f64, String> + Clone + Send + Sync + 'static {
        move |v| finite(v).and_then(|x| self.check(x))
    }
}

/// A lean angle in degrees, for clap's `value_parser`: a finite number strictly between -90
/// and 90.
pub fn lean_deg(v: &str) -> Result<f64, String> {
    let x = finite(v)?;
    if x.abs() >= 90.0 {
        return Err("must lie strictly between -90 and 90 degrees".into());
    }
    Ok(x)
}

/// The options beside `--model` that say how its file is read: `--rider FILE` (a
/// BicycleParameters rider file added to the rear frame, [`add_rider`]) and `--strict` (moments
/// of inertia breaking a triangle inequality are an error instead of a warning).
#[derive(Clone, Debug, Default, PartialEq, clap::Args)]
pub struct DataOptions {
    /// A BicycleParameters rider file (`name = value+/-sigma`) whose rider is added to the rear
    /// frame, or a Yeadon body measurement file (`<R>YeadonMeas.txt`) seated on the bicycle as
    /// BicycleParameters' add_rider(reCalc=True) seats it
    #[arg(long, value_name = "FILE.txt")]
    pub rider: Option<String>,
    /// With a Yeadon measurement file as --rider: yeadon's configuration file (its somersault
    /// and the joint angles the seating does not solve) (default: `<R><B>YeadonCFG.txt` beside
    /// the measurement file, BicycleParameters' layout)
    #[arg(long, value_name = "FILE.txt", requires = "rider")]
    pub rider_config: Option<String>,
    /// With a Yeadon measurement file as --rider: the bicycle's measured geometry (seat, bottom
    /// bracket, handlebar: hbb, lcs, lsp, lst, lamst, whb, LhbR, LhbF) (default:
    /// `bicycles/<B>/RawData/<B>Measured.txt` of BicycleParameters' layout)
    #[arg(long, value_name = "FILE.txt", requires = "rider")]
    pub measured: Option<String>,
    /// A moment of inertia breaking a triangle inequality is an error instead of a warning
    #[arg(long)]
    pub strict: bool,
}

impl DataOptions {
    /// Whether any is given.
    pub fn any(&self) -> bool {
        self.rider.is_some()
            || self.strict
            || self.rider_config.is_some()
            || self.measured.is_some()
    }

    /// The bicycle as outputs name it: `model`, or `model with rider RIDER` when a rider was
    /// added, so that no output looks the same with and without `--rider`.
    pub fn label(&self, model: &str) -> String {
        match &self.rider {
            Some(r) => format!("{model} with rider {r}"),
            None => model.to_string(),
        }
    }
}

/// The bicycle `benchmark` or the one in the parameter file `model` read as `data` says: with
/// its rider added, and broken triangle inequalities printed as warnings on standard error
/// (errors with `--strict`).
pub fn bicycle(model: &str, data: &DataOptions) -> Result<WhippleParams, String> {
    uncertain_bicycle(model, data).map(|(u, _)| u.params)
}

/// As [`bicycle`], with the standard deviations the file states (carried through the rider)
/// and the warnings printed.
pub fn uncertain_bicycle(
    model: &str,
    data: &DataOptions,
) -> Result<(UncertainParams, Vec<String>), String> {
    let (params, warnings) = read_bicycle(model, data)?;
    for w in &warnings {
        eprintln!("warning: {w}");
    }
    Ok((params, warnings))
}

/// The side view of the bicycle of `model` with the rider of `data` drawn apart (the bicycle
/// read without it; its warnings are those [`uncertain_bicycle`] prints).
pub fn side_view(
    model: &str,
    data: &DataOptions,
) -> Result<carvallo::whipple::drawing::SideView, String> {
    let bare = DataOptions { rider: None, strict: data.strict, ..DataOptions::default() };
    let (params, _) = read_bicycle(model, &bare)?;
    let rider = match data.rider.as_deref() {
        Some(path) => Some(rider_on(path, model, data, &params)?),
        None => None,
    };
    Ok(carvallo::whipple::drawing::SideView::new(&params.params, rider.as_ref()))
}

/// The name `--model` gives Moore's (2012) leaning rider with BicycleParameters' Browser +
/// Jason ([`LeanRiderParams::browser_jason`]).
pub const LEAN_RIDER: &str = "lean-rider";

/// The commands that take the leaning rider, for the error of the others.
pub const LEAN_RIDER_COMMANDS: &str =
    "eig, window, statespace, bode, simulate, turn and plot eigenvalues";

/// The leaning rider when `model` names it: `lean-rider`, or a parameter file in Moore's names
/// ([`LeanRiderParams::looks_like`]); `None` for any other model. `--rider` and `--strict`
/// read a bicycle file and are errors with it.
pub fn lean_rider(model: &str, data: &DataOptions) -> Result<Option<LeanRider>, String> {
    let params = if model == LEAN_RIDER {
        LeanRiderParams::browser_jason()
    } else if model == "benchmark" || std::fs::metadata(model).is_err() {
        return Ok(None);
    } else {
        let text = read_model_file(model)?;
        if !LeanRiderParams::looks_like(&text) {
            return Ok(None);
        }
        LeanRiderParams::from_text(&text)
            .map_err(|e| format!("invalid leaning-rider file `{model}`: {e}"))?
    };
    if data.any() {
        return Err(format!(
            "`--rider` and `--strict` read a bicycle file; `{model}` is the leaning rider, whose \
             rider is in its parameters"
        ));
    }
    LeanRider::new(params).map(Some).map_err(|e| format!("invalid leaning rider `{model}`: {e}"))
}

/// As [`uncertain_bicycle`], the warnings returned, not printed.
fn read_bicycle(model: &str, data: &DataOptions) -> Result<(UncertainParams, Vec<String>), String> {
    let not_yet = || {
        format!(
            "`{model}` is the leaning rider (Moore 2012): this command does not take it yet; \
             {LEAN_RIDER_COMMANDS} do"
        )
    };
    if model == LEAN_RIDER {
        return Err(not_yet());
    }
    let loaded = if model == "benchmark" {
        Loaded { params: UncertainParams::exact(WhippleParams::benchmark()), warnings: Vec::new() }
    } else {
        let text = read_model_file(model)?;
        if LeanRiderParams::looks_like(&text) {
            return Err(not_yet());
        }
        let read = if text.lines().any(|l| l.trim_start().starts_with('[')) {
            UncertainParams::from_any(&text).map(|params| Loaded { params, warnings: Vec::new() })
        } else {
            UncertainParams::read(&text, data.strict)
        };
        read.map_err(|e| {
            if Rider::from_text(&text).is_ok() {
                format!(
                    "invalid model file `{model}`: it is a rider file (the rider's mB, xB, zB and \
                     inertia), not a bicycle: give a bicycle as --model and this file as --rider"
                )
            } else {
                format!("invalid model file `{model}`: {e}")
            }
        })?
    };
    let loaded = match &data.rider {
        None => loaded,
        Some(path) => {
            let rider = rider_on(path, model, data, &loaded.params)?;
            add_rider(&loaded.params, &rider)
                .map_err(|e| format!("invalid rider file `{path}` on `{model}`: {e}"))?
        }
    };
    if data.strict {
        if let Some(w) = loaded.warnings.first() {
            return Err(format!(
                "invalid model file `{model}`: {} (--strict)",
                w.to_string().replace("; computed as given", "")
            ));
        }
    }
    let warnings: Vec<String> = loaded.warnings.iter().map(|w| format!("{model}: {w}")).collect();
    Ok((loaded.params, warnings))
}

/// The name of a bicycle for titles and file names: `Benchmark bicycle` for `benchmark`,
/// `Leaning rider (Browser + Jason)` for `lean-rider`, or the stem
/// of the parameter file without BicycleParameters' `Benchmark` suffix
/// (`…/BrowserBenchmark.txt` → `Browser`), and with a rider `bicycle + rider`, the rider's stem
/// without that suffix and without the bicycle's name (`JasonBrowserBenchmark.txt` on Browser →
/// `Browser + Jason`).
pub fn bicycle_name(model: &str, rider: Option<&str>) -> String {
    let stem = |path: &str| {
        let s = std::path::Path::new(path)
            .file_stem()
            .map_or_else(|| path.to_string(), |s| s.to_string_lossy().into_owned());
        match s.strip_suffix("Benchmark") {
            Some(head) if !head.is_empty() => head.to_string(),
            _ => s,
        }
    };
    let bike = match model {
        "benchmark" => "Benchmark bicycle".to_string(),
        LEAN_RIDER => "Leaning rider (Browser + Jason)".to_string(),
        _ => stem(model),
    };
    match rider {
        None => bike,
        Some(r) => {
            let r = stem(r);
            let r = match r.strip_suffix(bike.as_str()) {
                Some(head) if !head.is_empty() => head.to_string(),
                _ => r,
            };
            format!("{bike} + {r}")
        }
    }
}

/// A name as the start of a file name: lower case, each run of other characters than ASCII
/// letters and digits one `_` (`Browser + Jason` → `browser_jason`); `bicycle` if nothing is
/// left, and `benchmark` for the benchmark bicycle alone (the report's `benchmark_*.svg`).
pub fn file_stem_of(name: &str) -> String {
    if name == "Benchmark bicycle" {
        return "benchmark".to_string();
    }
    let mut out = String::new();
    for ch in name.chars() {
        if ch.is_ascii_alphanumeric() {
            out.push(ch.to_ascii_lowercase());
        } else if !out.is_empty() && !out.ends_with('_') {
            out.push('_');
        }
    }
    let out = out.trim_end_matches('_').to_string();
    if out.is_empty() {
        "bicycle".to_string()
    } else {
        out
    }
}

/// The rider of the file `path` on the bicycle `params` of `model`: a BicycleParameters rider
/// file as it is, or a Yeadon measurement file seated on the bicycle
/// ([`carvallo::whipple::yeadon::seat_on_bicycle`], the Published variant that equals
/// BicycleParameters' `add_rider(reCalc=True)`) with the configuration and measured geometry of
/// `data` or of BicycleParameters' layout; what was done is said on standard error.
pub fn rider_on(
    path: &str,
    model: &str,
    data: &DataOptions,
    params: &UncertainParams,
) -> Result<Rider, String> {
    use carvallo::whipple::yeadon as y;
    let text = read_text(path, "rider file")?;
    if !y::Measurements::looks_like(&text) {
        return Rider::from_text(&text).map_err(|e| format!("invalid rider file `{path}`: {e}"));
    }
    let invalid = |e: &dyn std::fmt::Display| format!("invalid rider file `{path}`: {e}");
    let meas = y::Measurements::from_text(&text).map_err(|e| invalid(&e))?;
    let layout =
        y::bicycleparameters_files(std::path::Path::new(path), std::path::Path::new(model));
    let needs = |option: &str, what: &str| {
        format!(
            "invalid rider file `{path}`: a Yeadon measurement file needs {what} ({option} FILE; \
             BicycleParameters' layout names none for `{model}`)"
        )
    };
    let cfg_path = match (&data.rider_config, &layout) {
        (Some(c), _) => c.clone(),
        (None, Some((c, _))) => c.display().to_string(),
        (None, None) => return Err(needs("--rider-config", "a configuration file")),
    };
    let measured_path = match (&data.measured, &layout) {
        (Some(m), _) => m.clone(),
        (None, Some((_, m))) => m.display().to_string(),
        (None, None) => return Err(needs("--measured", "the bicycle's measured geometry")),
    };
    let cfg = y::Configuration::from_text(&read_text(&cfg_path, "rider file")?)
        .map_err(|e| format!("invalid rider file `{cfg_path}` (Yeadon configuration): {e}"))?;
    let g = y::SeatingGeometry::from_measured(
        &read_text(&measured_path, "rider file")?,
        &params.params,
    )
    .map_err(|e| format!("invalid rider file `{measured_path}` (measured geometry): {e}"))?;
    let seated = y::seat_on_bicycle(&meas, &cfg, &g, y::Variant::Published)
        .map_err(|e| format!("invalid rider file `{path}` on `{model}`: {e}"))?;
    eprintln!(
        "note: rider `{path}`: Yeadon body measurements, configuration `{cfg_path}`, bicycle \
         geometry `{measured_path}`: {}",
        y::describe(&seated)
    );
    for n in &seated.notes {
        eprintln!("note: rider `{path}`: {n}");
    }
    Ok(seated.rider)
}

/// Whether `message` (an error of a command) is about the data of a file rather than the
/// command line: it is printed without the usage text. The messages of [`bicycle`] and
/// [`uncertain_bicycle`] start so.
pub fn is_data_error(message: &str) -> bool {
    [
        "invalid model file `",
        "cannot read model file `",
        "invalid rider file `",
        "cannot read rider file `",
        "invalid gain table `",
        "cannot read gain table `",
        "invalid raw measurement file `",
        "cannot read raw measurement file `",
    ]
    .iter()
    .any(|p| message.starts_with(p))
}

/// The bicycle `benchmark` or the one in the TOML parameter file `model` (the anchors format
/// only), for `accel`.
pub fn toml_model(model: &str) -> Result<WhippleParams, String> {
    if model == "benchmark" {
        return Ok(WhippleParams::benchmark());
    }
    let text = read_model_file(model)?;
    WhippleParams::from_toml_str(&text).map_err(|e| format!("invalid model file `{model}`: {e}"))
}

/// The text of the parameter file `model`.
fn read_model_file(model: &str) -> Result<String, String> {
    read_text(model, "model file")
}

/// The most bytes read from one input file (parameter, rider, gain, torque and batch files) or
/// from standard input: far above any real input, low enough that `--model /dev/zero` fails at
/// once instead of filling the memory.
pub const MAX_INPUT_BYTES: u64 = 16 << 20;

/// The text of the file `path`, read whole up to [`MAX_INPUT_BYTES`]; a file that is not a
/// regular file (a device, a pipe) is read with the same bound. Errors start with `cannot read
/// {what} `path``, and name the bound for a file larger than it.
pub fn read_text(path: impl AsRef<std::path::Path>, what: &str) -> Result<String, String> {
    let path = path.as_ref();
    let cannot = |reason: String| format!("cannot read {what} `{}`: {reason}", path.display());
    let file = std::fs::File::open(path).map_err(|e| cannot(e.to_string().to_lowercase()))?;
    if file.metadata().is_ok_and(|m| m.is_dir()) {
        return Err(cannot("it is a directory".into()));
    }
    read_bounded(file).map_err(cannot)
}

/// Everything `reader` gives, as UTF-8 text, up to [`MAX_INPUT_BYTES`] (an error past it).
pub fn read_bounded(reader: impl std::io::Read) -> Result<String, String> {
    use std::io::Read as _;
    let mut bytes = Vec::new();
    reader
        .take(MAX_INPUT_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| e.to_string().to_lowercase())?;
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(format!("larger than {} MiB, the limit of an input", MAX_INPUT_BYTES >> 20));
    }
    String::from_utf8(bytes).map_err(|e| {
        format!("not UTF-8 text (invalid byte at offset {})", e.utf8_error().valid_up_to())
    })
}

/// Parses `words` (the command's name first) as the options `A` of one command, as the command
/// line would (for the subcommands' tests); the error is clap's message.
#[cfg(test)]
pub fn parse<A: clap::Args>(words: &[&str]) -> Result<A, String> {
    use clap::Parser as _;
    #[derive(clap::Parser)]
    struct One<A: clap::Args> {
        #[command(flatten)]
        args: A,
    }
    One::<A>::try_parse_from(words).map(|one| one.args).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_must_be_finite_and_leans_within_a_right_angle() {
        assert_eq!(finite("2.5"), Ok(2.5));
        assert_eq!(finite("five"), Err("not a number".into()));
        assert_eq!(finite("inf"), Err("must be finite".into()));
        assert_eq!(lean_deg("-89.9"), Ok(-89.9));
        assert_eq!(lean_deg("90"), Err("must lie strictly between -90 and 90 degrees".into()));
    }

    #[test]
    fn inputs_are_read_up_to_a_stated_bound() {
        // A device without end, a directory, bytes that are not UTF-8 and a file just at the
        // bound (read) and one byte past it (refused).
        let e = read_text("/dev/zero", "model file").unwrap_err();
        assert_eq!(
            e,
            "cannot read model file `/dev/zero`: larger than 16 MiB, the limit of an input"
        );
        let e = read_text("/", "rider file").unwrap_err();
        assert_eq!(e, "cannot read rider file `/`: it is a directory");
        let e = read_bounded(&[b'a', 0xff][..]).unwrap_err();
        assert_eq!(e, "not UTF-8 text (invalid byte at offset 1)");
        let at = vec![b' '; MAX_INPUT_BYTES as usize];
        assert_eq!(read_bounded(&at[..]).map(|t| t.len()), Ok(at.len()));
        let past = vec![b' '; MAX_INPUT_BYTES as usize + 1];
        assert!(read_bounded(&past[..]).unwrap_err().starts_with("larger than 16 MiB"));
    }

    #[test]
    fn bicycles_are_named_by_their_files_stems() {
        let bike = "data/bicycleparameters/bicycles/Browser/Parameters/BrowserBenchmark.txt";
        let rider = "data/bicycleparameters/riders/Jason/Parameters/JasonBrowserBenchmark.txt";
        assert_eq!(bicycle_name(bike, None), "Browser");
        assert_eq!(bicycle_name(bike, Some(rider)), "Browser + Jason");
        assert_eq!(bicycle_name("benchmark", None), "Benchmark bicycle");
        assert_eq!(file_stem_of("Benchmark bicycle"), "benchmark");
        assert_eq!(
            bicycle_name("designs/light.toml", Some("r/Benchmark.txt")),
            "light + Benchmark"
        );
        assert_eq!(file_stem_of("Browser + Jason"), "browser_jason");
        assert_eq!(file_stem_of(" +é "), "bicycle");
    }

    #[test]
    fn models_are_named_in_their_errors() {
        assert_eq!(bicycle("benchmark", &DataOptions::default()), Ok(WhippleParams::benchmark()));
        for e in [
            bicycle("/nonexistent/bike.toml", &DataOptions::default()).unwrap_err(),
            toml_model("/nonexistent/bike.toml").unwrap_err(),
        ] {
            assert!(e.starts_with("cannot read model file `/nonexistent/bike.toml`"), "{e}");
        }
    }
}
