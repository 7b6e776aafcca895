//! The state-feedback options shared by `window`, `eig` and `sweep`: `--gain NAME=VALUE`,
//! `--gain NAME=FROM:TO:COUNT` (a sweep axis), `--gain-table FILE.csv`, and the closed-loop
//! window's text and JSON.
//!
//! The gains are those of $u = -Kx$ named `k_{input}_{state}`
//! ([`carvallo::whipple::feedback::GAIN_NAMES`]); a gain not given is zero. An unknown name is
//! a usage error naming it and listing the valid ones (exit code 2). A gain table is a CSV file
//! with the header `speed,k_...` (any subset of the gain names, in any order) and one row of
//! numbers per speed, speeds increasing; its errors name the file.

use carvallo::whipple::feedback::{ClosedLoopWindow, GainTable, Gains, GAIN_NAMES};
use carvallo::whipple::lean_rider::LeanGains;
use serde_json::{json, Value};

use crate::args::{GAIN, SPEED};

/// One `--gain NAME=VALUE`.
#[derive(Clone, Debug, PartialEq)]
pub struct GainValue {
    /// The gain's name (one of the valid names).
    pub name: String,
    /// Its value.
    pub value: f64,
}

/// One `--gain NAME=FROM:TO:COUNT` of `sweep`.
#[derive(Clone, Debug, PartialEq)]
pub struct GainAxis {
    /// The gain's name (one of the valid names).
    pub name: String,
    /// The first value.
    pub from: f64,
    /// The last value.
    pub to: f64,
    /// The number of values (at least 1; one value is `from`).
    pub count: usize,
}

impl GainAxis {
    /// The `i`-th value.
    pub fn value(&self, i: usize) -> f64 {
        if self.count == 1 {
            self.from
        } else if i + 1 == self.count {
            self.to
        } else {
            self.from + (self.to - self.from) * i as f64 / (self.count - 1) as f64
        }
    }
}

/// Checks a gain name: the error names it and lists the valid ones.
fn gain_name(name: &str) -> Result<String, String> {
    if LeanGains::index(name).is_some() {
        return Ok(name.to_string());
    }
    Gains::index(name).map(|_| name.to_string()).map_err(|e| e.to_string())
}

/// An error for the first gain of `values` that only the leaning rider has (`k_lean_...`,
/// `k_..._lean`, `k_..._lean_rate`): the bicycle's feedback would drop it.
pub fn bicycle_only(values: &[GainValue]) -> Result<(), String> {
    match values.iter().find(|v| Gains::index(&v.name).is_err()) {
        Some(v) => Err(format!(
            "invalid --gain `{}`: a gain of the leaning rider (--model lean-rider); the \
             bicycle's are k_{{roll|steer}}_{{roll|steer|roll_rate|steer_rate}}",
            v.name
        )),
        None => Ok(()),
    }
}

/// The leaning rider's gains of the `--gain` options (the others zero).
pub fn lean_gains_of(values: &[GainValue]) -> Result<LeanGains, String> {
    LeanGains::from_named(values.iter().map(|v| (v.name.as_str(), v.value)))
}

/// A gain of `text` (the value of the option `what`): finite and within [`GAIN`].
fn number(s: &str, what: &str, text: &str) -> Result<f64, String> {
    let x: f64 = s.parse().map_err(|_| format!("invalid number `{s}` in {what} `{text}`"))?;
    if !x.is_finite() {
        return Err(format!("invalid number `{s}` in {what} `{text}`: must be finite"));
    }
    GAIN.check(x).map_err(|e| format!("invalid gain `{s}` in {what} `{text}`: {e}"))
}

/// Reads `NAME=VALUE` of `--gain` (clap's value parser).
pub fn parse_gain(text: &str) -> Result<GainValue, String> {
    let (name, value) = text
        .split_once('=')
        .ok_or_else(|| format!("invalid --gain `{text}`: expected NAME=VALUE"))?;
    Ok(GainValue { name: gain_name(name)?, value: number(value, "--gain", text)? })
}

/// Reads `NAME=FROM:TO:COUNT` of `sweep --gain` (clap's value parser).
pub fn parse_gain_axis(text: &str) -> Result<GainAxis, String> {
    let bad = || format!("invalid --gain `{text}`: expected NAME=FROM:TO:COUNT");
    let (name, range) = text.split_once('=').ok_or_else(bad)?;
    let parts: Vec<&str> = range.split(':').collect();
    let [from, to, count] = parts[..] else { return Err(bad()) };
    let name = gain_name(name)?;
    let count: usize =
        count.parse().map_err(|_| format!("invalid count `{count}` in --gain `{text}`"))?;
    if count == 0 {
        return Err(format!("invalid count `0` in --gain `{text}`: must be at least 1"));
    }
    Ok(GainAxis {
        name,
        from: number(from, "--gain", text)?,
        to: number(to, "--gain", text)?,
        count,
    })
}

/// The gains of the `--gain` options (the others zero; a name given twice keeps its last
/// value).
pub fn gains_of(values: &[GainValue]) -> Gains {
    let mut g = Gains::ZERO;
    for v in values {
        // The names were checked by the value parser.
        let _ = g.set(&v.name, v.value);
    }
    g
}

/// A finite, non-negative speed, for clap's `value_parser` of `--vmin` and `--vmax`.
pub fn speed(v: &str) -> Result<f64, String> {
    let x = crate::args::finite(v)?;
    if x < 0.0 {
        return Err("must not be negative".into());
    }
    SPEED.check(x)
}

/// Reads the gain table `path` (see the [module docs](self)); errors start with
/// `invalid gain table` or `cannot read gain table` and name the file.
pub fn read_gain_table(path: &str) -> Result<GainTable, String> {
    let text = crate::args::read_text(path, "gain table")?;
    let bad = |msg: String| format!("invalid gain table `{path}`: {msg}");
    let mut lines = text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty());
    let (_, header) = lines.next().ok_or_else(|| bad("empty file".into()))?;
    let columns: Vec<&str> = header.split(',').map(str::trim).collect();
    if columns.first() != Some(&"speed") {
        return Err(bad(format!("the header must start with `speed`, not `{header}`")));
    }
    for (i, c) in columns.iter().enumerate().skip(1) {
        Gains::index(c).map_err(|e| bad(e.to_string()))?;
        if columns[1..i].contains(c) {
            return Err(bad(format!("the column `{c}` is given twice")));
        }
    }
    let mut rows = Vec::new();
    for (n, line) in lines {
        let cells: Vec<&str> = line.split(',').map(str::trim).collect();
        if cells.len() != columns.len() {
            return Err(bad(format!(
                "line {}: {} values for {} columns",
                n + 1,
                cells.len(),
                columns.len()
            )));
        }
        let mut values = Vec::with_capacity(cells.len());
        for cell in &cells {
            let x: f64 =
                cell.parse().ok().filter(|x: &f64| x.is_finite()).ok_or_else(|| {
                    bad(format!("line {}: `{cell}` is not a finite number", n + 1))
                })?;
            let range = if values.is_empty() { SPEED } else { GAIN };
            let what = if values.is_empty() { "speed" } else { "gain" };
            let x = range
                .check(x)
                .map_err(|e| bad(format!("line {}: the {what} `{cell}` {e}", n + 1)))?;
            values.push(x);
        }
        let mut g = Gains::ZERO;
        for (c, x) in columns[1..].iter().zip(&values[1..]) {
            let _ = g.set(c, *x);
        }
        rows.push((values[0], g));
    }
    GainTable::new(rows).map_err(|e| bad(e.to_string().replace("invalid gain table: ", "")))
}

/// A JSON number, `null` for an infinite speed.
fn finite(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else {
        Value::Null
    }
}

/// The eight gains as a JSON object by name.
pub fn gains_json(g: &Gains) -> Value {
    let values = g.values();
    Value::Object(GAIN_NAMES.iter().zip(values).map(|(n, x)| (n.to_string(), json!(x))).collect())
}

/// The nonzero gains as `name = value, ...` (or `none`).
pub fn gains_text(g: &Gains) -> String {
    let list: Vec<String> = GAIN_NAMES
        .iter()
        .zip(g.values())
        .filter(|(_, x)| *x != 0.0)
        .map(|(n, x)| format!("{n} = {x}"))
        .collect();
    if list.is_empty() {
        "none".into()
    } else {
        list.join(", ")
    }
}

/// The stable intervals as JSON pairs, an infinite end as `null`.
pub fn stable_json(w: &ClosedLoopWindow) -> Value {
    w.stable.iter().map(|&(a, b)| json!([finite(a), finite(b)])).collect()
}

/// The closed-loop window's text: the speed range looked at, then one line per stable
/// interval (or `no stable speed`).
pub fn window_text(w: &ClosedLoopWindow) -> String {
    let upper = |x: f64| if x.is_finite() { format!("{x} m/s") } else { "any speed".to_string() };
    let mut s = format!("speeds from {} m/s to {}\n", w.from, upper(w.to));
    if w.stable.is_empty() {
        s.push_str("no stable speed\n");
    }
    for &(a, b) in &w.stable {
        s.push_str(&format!("closed-loop stable from {a} to {}\n", upper(b)));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gains_parse_and_unknown_names_list_the_valid_ones() {
        assert_eq!(
            parse_gain("k_steer_roll_rate=-10"),
            Ok(GainValue { name: "k_steer_roll_rate".into(), value: -10.0 })
        );
        let e = parse_gain("k_yaw=1").unwrap_err();
        assert!(e.starts_with("unknown gain `k_yaw`: expected one of k_roll_roll,"), "{e}");
        assert!(parse_gain("k_roll_roll").unwrap_err().contains("expected NAME=VALUE"));
        assert!(parse_gain("k_roll_roll=inf").unwrap_err().contains("must be finite"));
        let axis = parse_gain_axis("k_roll_roll=0:10:3").expect("ok");
        assert_eq!((axis.value(0), axis.value(1), axis.value(2)), (0.0, 5.0, 10.0));
        assert!(parse_gain_axis("k_roll_roll=0:10:0").unwrap_err().contains("at least 1"));
        assert!(parse_gain_axis("k_x=0:10:2").unwrap_err().starts_with("unknown gain `k_x`"));
        assert!(parse_gain_axis("k_roll_roll=0:10").unwrap_err().contains("FROM:TO:COUNT"));
        let g = gains_of(&[parse_gain("k_roll_roll=2").unwrap()]);
        assert_eq!(gains_text(&g), "k_roll_roll = 2");
        assert_eq!(gains_json(&g)["k_roll_roll"], 2.0);
        assert_eq!(speed("-1"), Err("must not be negative".into()));
    }

    #[test]
    fn gain_tables_are_read_and_their_errors_name_the_file() {
        let dir = std::env::temp_dir().join(format!("carvallo-gains-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let file = |name: &str, text: &str| {
            let p = dir.join(name);
            std::fs::write(&p, text).expect("write");
            p.to_string_lossy().into_owned()
        };
        let ok = file("ok.csv", "speed,k_steer_roll_rate\n0,-20\n10,0\n");
        let t = read_gain_table(&ok).expect("valid");
        assert_eq!(t.at(5.0).and_then(|g| g.get("k_steer_roll_rate")), Some(-10.0));
        for (name, text, msg) in [
            ("h.csv", "v,k_roll_roll\n0,1\n1,1\n", "the header must start with `speed`"),
            ("n.csv", "speed,k_yaw\n0,1\n1,1\n", "unknown gain `k_yaw`"),
            ("c.csv", "speed,k_roll_roll\n0,1,2\n1,1\n", "line 2: 3 values for 2 columns"),
            ("x.csv", "speed,k_roll_roll\n0,x\n1,1\n", "line 2: `x` is not a finite number"),
            ("d.csv", "speed,k_roll_roll\n1,1\n0,1\n", "speed 0 in row 2 does not increase"),
            ("o.csv", "speed,k_roll_roll\n1,1\n", "1 rows: at least two speeds are needed"),
        ] {
            let path = file(name, text);
            let e = read_gain_table(&path).unwrap_err();
            assert!(e.starts_with(&format!("invalid gain table `{path}`: ")), "{e}");
            assert!(e.contains(msg), "{e}");
        }
        let e = read_gain_table("/nonexistent/gains.csv").unwrap_err();
        assert!(e.starts_with("cannot read gain table `/nonexistent/gains.csv`"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
