//! `carvallo statespace --model benchmark|FILE --speed V[,V...] [--json]`: the state space
//! $\dot x = A x + B u$ of the linearised Carvallo–Whipple bicycle, $x = (\varphi, \delta,
//! \dot\varphi, \dot\delta)$, $u = (T_\varphi, T_\delta)$ (roll and steer torque), $C = I$,
//! $D = 0$ ([`carvallo::whipple::plant`]). JSON `{"speed", "A", "B"}` with row-major nested
//! arrays, or a list of them for several speeds.
//!
//! The parameter file is read as for `window` ([`crate::args::bicycle`], with `--rider FILE`
//! and `--strict`). A speed that is not a finite number and an unreadable or invalid parameter
//! file are usage errors: a message naming the value, exit code 2.

use carvallo::whipple::plant::StateSpace;
use carvallo::whipple::Whipple;
use serde_json::{json, Value};

use crate::args::DataOptions;

/// `carvallo statespace`: A and B at one or several speeds.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The bicycle: `benchmark` or a parameter file (the anchors' TOML or BicycleParameters'
    /// `name = value+/-sigma` text); or Moore's leaning rider: `lean-rider` (Browser + Jason)
    /// or a file in Moore's names
    #[arg(long, value_name = "MODEL")]
    pub model: String,
    #[command(flatten)]
    pub data: DataOptions,
    /// The forward speeds (m/s), separated by commas
    #[arg(long, value_name = "V", required = true, value_delimiter = ',',
          value_parser = crate::args::SPEED.parser(), allow_hyphen_values = true)]
    pub speed: Vec<f64>,
    /// Print JSON `{speed, A, B}` (a list of them for several speeds) instead of text
    #[arg(long)]
    pub json: bool,
}

fn to_json(ss: &StateSpace) -> Value {
    json!({ "speed": ss.speed, "A": ss.a_rows(), "B": ss.b_rows() })
}

fn to_text(ss: &StateSpace) -> String {
    let mut s = format!(
        "state space at {} m/s, x = (roll, steer, roll rate, steer rate), \
         u = (roll torque, steer torque), C = I, D = 0\nA =\n",
        ss.speed
    );
    for row in ss.a_rows() {
        let cells: Vec<String> = row.iter().map(|x| format!("{x:>22}")).collect();
        s.push_str(&format!("{}\n", cells.join(" ")));
    }
    s.push_str("B =\n");
    for row in ss.b_rows() {
        let cells: Vec<String> = row.iter().map(|x| format!("{x:>22}")).collect();
        s.push_str(&format!("{}\n", cells.join(" ")));
    }
    s
}

/// Runs `carvallo statespace`: the text to print, or an error naming the bad value.
pub fn run(cmd: &Args) -> Result<String, String> {
    let Args { model, data, speed, json } = cmd;
    if let Some(rider) = crate::args::lean_rider(model, data)? {
        return super::lean_rider::statespace(model, &rider, speed, *json);
    }
    let spaces = Whipple::new(crate::args::bicycle(model, data)?).state_spaces(speed);
    if data.rider.is_some() {
        // Say that a rider was added: the matrices alone look the same with and without.
        let heading = format!("{}\n", data.label(model));
        if !*json {
            return Ok(heading + &spaces.iter().map(to_text).collect::<Vec<_>>().join("\n"));
        }
        let with = |ss| {
            let mut v = to_json(ss);
            v["model"] = json!(model);
            v["rider"] = json!(data.rider);
            v
        };
        let v = match spaces.as_slice() {
            [one] => with(one),
            many => Value::Array(many.iter().map(with).collect()),
        };
        return serde_json::to_string_pretty(&v).map_err(|e| e.to_string());
    }
    if *json {
        let v = match spaces.as_slice() {
            [one] => to_json(one),
            many => Value::Array(many.iter().map(to_json).collect()),
        };
        serde_json::to_string_pretty(&v).map_err(|e| e.to_string())
    } else {
        Ok(spaces.iter().map(to_text).collect::<Vec<_>>().join("\n"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    #[test]
    fn parses_lists_and_rejects_by_value() {
        assert_eq!(
            parse::<Args>(&["statespace", "--speed", "5", "--model", "b.toml"]),
            Ok(Args {
                model: "b.toml".into(),
                data: DataOptions::default(),
                speed: vec![5.0],
                json: false
            })
        );
        assert_eq!(
            parse::<Args>(&["statespace", "--speed", "-1,0,2.5", "--model", "b"]).map(|a| a.speed),
            Ok(vec![-1.0, 0.0, 2.5])
        );
        let e = parse::<Args>(&["statespace", "--model", "x", "--speed", "1,fast"]).unwrap_err();
        assert!(
            e.starts_with("error: invalid value 'fast' for '--speed <V>': not a number"),
            "{e}"
        );
        let e = parse::<Args>(&["statespace", "--model", "x", "--speed", "1,inf"]).unwrap_err();
        assert!(e.contains("'inf'") && e.contains("must be finite"), "{e}");
        let e = parse::<Args>(&["statespace", "--model", "benchmark"]).unwrap_err();
        assert!(e.contains("--speed <V>"), "{e}");
    }

    #[test]
    fn json_is_one_object_or_a_list_and_b_inverts_m() {
        let one = |speeds: Vec<f64>| {
            let a = Args {
                model: "benchmark".into(),
                data: DataOptions::default(),
                speed: speeds,
                json: true,
            };
            serde_json::from_str::<Value>(&run(&a).unwrap()).unwrap()
        };
        let v = one(vec![5.0]);
        assert_eq!(v["speed"], 5.0);
        assert_eq!(v["A"][0], json!([0.0, 0.0, 1.0, 0.0]));
        // M B_lower = I with the published benchmark M (Meijaard et al. 2007, eq. 5.3).
        let m = [[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]];
        let b = |i: usize, j: usize| v["B"][i][j].as_f64().unwrap();
        for (i, row) in m.iter().enumerate() {
            for j in 0..2 {
                let p = row[0] * b(2, j) + row[1] * b(3, j);
                assert!((p - f64::from(u8::from(i == j))).abs() < 1e-12, "{i}{j}: {p}");
            }
        }
        let list = one(vec![1.0, 2.0]);
        assert_eq!(list.as_array().map(Vec::len), Some(2));
        assert_eq!(list[1]["speed"], 2.0);
    }
}
