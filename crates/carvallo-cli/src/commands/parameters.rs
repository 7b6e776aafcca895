//! `carvallo parameters --raw FILE [--out FILE]`: the benchmark parameters computed from
//! BicycleParameters' raw measurements (`RawData/<name>Measured.txt`) as
//! `Bicycle(name, pathToData, forceRawCalc=True)` computes them
//! ([`carvallo::whipple::raw`]), written as a parameter file `name = value+/-sigma` at full
//! precision (round-trip floats), which `--model` reads; a flywheel measured inside the front
//! wheel (`mD`, `IDxx`, `IDyy`) follows as comment lines, not part of the model. An unreadable or invalid file is an
//! error naming the file and the line or measurement, exit code 2; nothing is written then.

use carvallo::whipple::raw::benchmark_from_measured;

/// `carvallo parameters`: a parameter file from raw measurements.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// BicycleParameters' raw measurements (`<name>Measured.txt`: masses, geometry, pendulum
    /// orientations and periods)
    #[arg(long, value_name = "FILE")]
    pub raw: String,
    /// Write the parameter file to FILE instead of standard output
    #[arg(long, value_name = "FILE")]
    pub out: Option<String>,
}

/// The parameter text, or the error message (a data error: see [`crate::args::is_data_error`]).
pub fn run(a: &Args) -> Result<String, String> {
    let text = crate::args::read_text(&a.raw, "raw measurement file")?;
    let raw = benchmark_from_measured(&text)
        .map_err(|e| format!("invalid raw measurement file `{}`: {e}", a.raw))?;
    let mut out = raw.params.to_text();
    for (name, v, s) in &raw.extra {
        out.push_str(&format!(
            "# {name} = {v:?}+/-{s:?} (a flywheel in the front wheel, not in the model)\n"
        ));
    }
    match &a.out {
        None => Ok(out),
        Some(path) => {
            std::fs::write(path, &out)
                .map_err(|e| format!("cannot write `{path}`: {}", e.to_string().to_lowercase()))?;
            Ok(format!("wrote {path}"))
        }
    }
}
