//! The options of `carvallo sweep` ([`SweepArgs`]) and how they are read: shared by the
//! design sweep ([`crate::perf`]) and the gain sweep ([`crate::gain_sweep`]), which both
//! depend on this module and not on each other's.

use carvallo::sweep::{Spread, Vary};

/// How the stability of each design is decided.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum MethodArg {
    /// The closed-form Hurwitz route through the characteristic polynomial
    #[default]
    Hurwitz,
    /// The eigenvalues of the state matrix at every speed
    Eigen,
}

/// `carvallo sweep`: the stability windows of many designs, a grid or random designs around
/// the model, in parallel.
#[derive(Clone, Debug, PartialEq, clap::Args)]
#[command(group(clap::ArgGroup::new("designs").required(true).args(["vary", "random", "gain"])))]
pub struct SweepArgs {
    /// The bicycle around which designs vary: `benchmark` or a parameter file
    #[arg(long, value_name = "MODEL")]
    pub model: String,
    #[command(flatten)]
    pub data: crate::args::DataOptions,
    /// A grid axis: COUNT values of the parameter NAME from FROM to TO (several make a grid of
    /// every combination, the first varying slowest)
    #[arg(long, value_name = "NAME=FROM:TO:COUNT", value_parser = parse_vary, conflicts_with = "random")]
    pub vary: Vec<Vary>,
    /// N random designs around the model (with --spread)
    #[arg(long, value_name = "N", value_parser = parse_random, requires = "spread", allow_hyphen_values = true)]
    pub random: Option<usize>,
    /// A randomly varied parameter: NAME scaled by a uniform factor in [1 - REL, 1 + REL]
    #[arg(long, value_name = "NAME=REL", value_parser = parse_spread, requires = "random")]
    pub spread: Vec<Spread>,
    /// The seed of the random designs (the same seed gives the same designs on any number of
    /// threads) [default: 1]
    #[arg(long, value_name = "S", requires = "random", allow_hyphen_values = true)]
    pub seed: Option<u64>,
    /// How stability is decided
    #[arg(long, value_enum, default_value_t)]
    pub method: MethodArg,
    /// Print the summary as JSON
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// Print one CSV row per design (for pandas.read_csv)
    #[arg(long)]
    pub csv: bool,
    /// A gain axis of the state feedback u = -K x: COUNT values of the gain NAME (as for
    /// `window --gain`) from FROM to TO; sweeps the closed-loop stable speed range over the gains
    /// on the model (several make a grid)
    #[arg(long, value_name = "NAME=FROM:TO:COUNT", value_parser = crate::gains::parse_gain_axis, conflicts_with_all = ["vary", "random"], allow_hyphen_values = true)]
    pub gain: Vec<crate::gains::GainAxis>,
    /// The lowest speed of the closed-loop windows of --gain (m/s) [default: 0]
    #[arg(long, value_name = "V", value_parser = crate::gains::speed)]
    pub vmin: Option<f64>,
    /// The highest speed of the closed-loop windows of --gain (m/s) [default: every speed]
    #[arg(long, value_name = "V", value_parser = crate::gains::speed)]
    pub vmax: Option<f64>,
}

/// Reads `NAME=FROM:TO:COUNT`.
pub(crate) fn parse_vary(text: &str) -> Result<Vary, String> {
    let bad = || format!("invalid --vary `{text}`: expected NAME=FROM:TO:COUNT");
    let (name, range) = text.split_once('=').ok_or_else(bad)?;
    let parts: Vec<&str> = range.split(':').collect();
    let [from, to, count] = parts[..] else { return Err(bad()) };
    let num = |s: &str| -> Result<f64, String> {
        let x: f64 = s.parse().map_err(|_| format!("invalid number `{s}` in --vary `{text}`"))?;
        if x.is_finite() {
            Ok(x)
        } else {
            Err(format!("invalid number `{s}` in --vary `{text}`: must be finite"))
        }
    };
    let count: usize = count.parse().map_err(|e: std::num::ParseIntError| {
        if *e.kind() == std::num::IntErrorKind::PosOverflow {
            format!("invalid count `{count}` in --vary `{text}`: more than {} designs", usize::MAX)
        } else {
            format!("invalid count `{count}` in --vary `{text}`")
        }
    })?;
    if count == 0 {
        return Err(format!("invalid count `0` in --vary `{text}`: must be at least 1"));
    }
    Ok(Vary { name: name.to_string(), from: num(from)?, to: num(to)?, count })
}

/// Reads `NAME=REL` of `--spread`.
pub(crate) fn parse_spread(text: &str) -> Result<Spread, String> {
    let (name, rel) = text
        .split_once('=')
        .ok_or_else(|| format!("invalid --spread `{text}`: expected NAME=REL"))?;
    let rel: f64 =
        rel.parse().map_err(|_| format!("invalid spread `{rel}` in --spread `{text}`"))?;
    if !(0.0..1.0).contains(&rel) {
        return Err(format!("invalid spread `{rel}` in --spread `{text}`: must lie in [0, 1)"));
    }
    Ok(Spread { name: name.to_string(), rel })
}

/// Reads the count `N` of `--random`: at least 1.
pub(crate) fn parse_random(v: &str) -> Result<usize, String> {
    match v.parse::<usize>() {
        Ok(n) if n >= 1 => Ok(n),
        Err(e) if *e.kind() == std::num::IntErrorKind::PosOverflow => {
            Err(format!("more than {} designs", usize::MAX))
        }
        _ => Err("expected a count of at least 1".into()),
    }
}
