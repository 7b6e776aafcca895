//! `carvallo eig --model benchmark|FILE.toml --speed V [--json]`: the four eigenvalues of the
//! linearised Carvallo–Whipple bicycle at speed V, as JSON
//! `{ "speed", "eigenvalues": [{"re", "im"}, ...] }`.
//!
//! The parameter file is read as for `window` ([`crate::args::bicycle`], with `--rider FILE` and `--strict`). Unknown or missing
//! arguments, a speed that is not a finite number and an unreadable or invalid parameter file
//! are usage errors: a message naming the value, exit code 2.

use carvallo::whipple::Whipple;

use crate::args::DataOptions;
use serde_json::{json, Value};

/// The usage `eig` prints: the one of `window` and `eig` together.
pub const HELP: &str = super::window::HELP;

#[derive(Debug, PartialEq)]
struct Command {
    model: String,
    data: DataOptions,
    speed: f64,
    json: bool,
}

fn parse(args: &[String]) -> Result<Command, String> {
    let (mut model, mut speed, mut json) = (None, None, false);
    let mut data = DataOptions::default();
    let mut it = args.iter().skip(1);
    while let Some(arg) = it.next() {
        if data.take(arg, &mut it)? {
            continue;
        }
        match arg.as_str() {
            "--json" if json => return Err("argument `--json` given more than once".into()),
            "--json" => json = true,
            "--model" if model.is_some() => {
                return Err("argument `--model` given more than once".into())
            }
            "--model" => {
                model = Some(it.next().ok_or("missing value after `--model`")?.clone());
            }
            "--speed" if speed.is_some() => {
                return Err("argument `--speed` given more than once".into())
            }
            "--speed" => {
                let v = it.next().ok_or("missing value after `--speed`")?;
                let x: f64 = v.parse().map_err(|_| format!("invalid speed `{v}`"))?;
                if !x.is_finite() {
                    return Err(format!("invalid speed `{v}`: must be finite"));
                }
                speed = Some(x);
            }
            _ => return Err(format!("unknown argument `{arg}`")),
        }
    }
    let model = model.ok_or("missing `--model benchmark|FILE.toml`")?;
    Ok(Command { model, data, speed: speed.ok_or("missing `--speed V`")?, json })
}

fn run(cmd: &Command) -> Result<String, String> {
    let Command { model, data, speed, json } = cmd;
    let ev = Whipple::new(crate::args::bicycle(model, data)?).eigenvalues(*speed);
    if *json {
        let list: Vec<Value> = ev.iter().map(|e| json!({ "re": e.re, "im": e.im })).collect();
        let v = json!({ "speed": speed, "eigenvalues": list });
        Ok(serde_json::to_string_pretty(&v).map_err(|e| e.to_string())?)
    } else {
        let mut s = format!("eigenvalues at {speed} m/s:\n");
        for e in &ev {
            s.push_str(&format!("{} {:+}i\n", e.re, e.im));
        }
        Ok(s)
    }
}

/// Runs `carvallo eig ARGS` (the argument list, the command's name first): the text to print,
/// or an error naming the bad argument or value.
pub fn main(args: &[String]) -> Result<String, String> {
    parse(args).and_then(|c| run(&c))
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::words as args;

    #[test]
    fn parses_and_rejects_by_value() {
        assert_eq!(
            parse(&args(&["eig", "--speed", "5", "--model", "b.toml"])),
            Ok(Command {
                model: "b.toml".into(),
                data: DataOptions::default(),
                speed: 5.0,
                json: false
            })
        );
        assert_eq!(
            parse(&args(&["eig", "--model", "x", "--speed", "fast"])),
            Err("invalid speed `fast`".into())
        );
        assert_eq!(
            parse(&args(&["eig", "--model", "benchmark"])),
            Err("missing `--speed V`".into())
        );
    }
}
