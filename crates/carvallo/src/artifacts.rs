//! Every artifact of `generated/` that the runtime embeds, in one table ([`MODELS`]): each
//! model's IR program (`generated/<model>.ir`) and the symbolic checks recorded at
//! regeneration (`generated/<model>.checks.tsv`), with the parser of those checks.
//!
//! The `scene!` macro reads the IR itself at compile time; the texts here serve the code that
//! reads a program or its checks at run time (the concordance report, the hoop discussion's
//! interpreter).

/// One model's committed artifacts, compiled in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Artifact {
    /// The model's name, as in `scene! { model: NAME }` and `generated/NAME.*`.
    pub model: &'static str,
    /// `generated/NAME.ir`: the straight-line program (`carvallo-ir 1`).
    pub ir: &'static str,
    /// `generated/NAME.checks.tsv`: the symbolic checks recorded at regeneration.
    pub checks: &'static str,
}

macro_rules! artifact {
    ($name:ident, $model:literal) => {
        #[doc = concat!("The artifacts of model `", $model, "`.")]
        pub const $name: Artifact = Artifact {
            model: $model,
            ir: include_str!(concat!("../../../generated/", $model, ".ir")),
            checks: include_str!(concat!("../../../generated/", $model, ".checks.tsv")),
        };
    };
}

artifact!(HOOP, "hoop");
artifact!(UNICYCLE, "unicycle");
artifact!(HOOP_DISCUSSION, "hoop_discussion");
artifact!(WHIPPLE, "whipple");
artifact!(WHIPPLE_NONLINEAR, "whipple_nonlinear");
artifact!(BICYCLE_GEOMETRY, "bicycle_geometry");
artifact!(BICYCLE_KINEMATICS, "bicycle_kinematics");
artifact!(BICYCLE_STEADY, "bicycle_steady");
artifact!(BICYCLE_STRAIGHT, "bicycle_straight");
artifact!(LEAN_RIDER, "lean_rider");
artifact!(WHEELED_PENDULUM, "wheeled_pendulum");

/// Every model with committed artifacts: the hoop and the unicycle (Part I), the modern
/// Carvallo–Whipple bicycle, then Carvallo's bicycle of Part II, then Moore's leaning rider
/// (from the mechanics engine), and the two-wheeled inverted pendulum (the engine's rolling
/// system that is not a bicycle).
pub const MODELS: [Artifact; 11] = [
    HOOP,
    UNICYCLE,
    HOOP_DISCUSSION,
    WHIPPLE,
    WHIPPLE_NONLINEAR,
    BICYCLE_GEOMETRY,
    BICYCLE_KINEMATICS,
    BICYCLE_STEADY,
    BICYCLE_STRAIGHT,
    LEAN_RIDER,
    WHEELED_PENDULUM,
];

/// The artifacts of `model`; `None` when no model of that name is embedded.
pub fn artifact(model: &str) -> Option<&'static Artifact> {
    MODELS.iter().find(|a| a.model == model)
}

/// One line of `generated/hoop.checks.tsv`.
#[derive(Clone, Debug, PartialEq)]
pub struct SymbolicCheck {
    /// Memoir section number.
    pub section: String,
    /// Stable identifier.
    pub id: String,
    /// Whether the check held at regeneration.
    pub holds: bool,
    /// What was checked.
    pub statement: String,
    /// The evidence.
    pub detail: String,
    /// The same check run again with its derived side perturbed (issue 38): what was changed
    /// and whether the check still held; `None` when the check states no perturbation.
    pub perturbed: Option<(String, bool)>,
}

/// Parses the checks TSV (`#` comment lines, then `section id holds statement detail
/// perturbation perturbed_holds` separated by tabs; `perturbed_holds` is `true`, `false` or `-`
/// when no perturbation is stated).
///
/// # Errors
/// A message naming the 1-based line and what is wrong with it.
pub fn parse_checks(tsv: &str) -> Result<Vec<SymbolicCheck>, String> {
    let mut checks = Vec::new();
    for (i, line) in tsv.lines().enumerate() {
        if line.starts_with('#') || line.trim().is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split('\t').collect();
        let [section, id, holds, statement, detail, perturbation, perturbed_holds] = fields[..]
        else {
            return Err(format!(
                "line {}: expected 7 tab-separated fields, found {}",
                i + 1,
                fields.len()
            ));
        };
        let flag = |name: &str, value: &str| match value {
            "true" => Ok(true),
            "false" => Ok(false),
            other => Err(format!("line {}: {name} must be true or false, found {other:?}", i + 1)),
        };
        let holds = flag("holds", holds)?;
        let perturbed = match perturbed_holds {
            "-" => None,
            value => Some((perturbation.to_string(), flag("perturbed_holds", value)?)),
        };
        checks.push(SymbolicCheck {
            section: section.to_string(),
            id: id.to_string(),
            holds,
            statement: statement.to_string(),
            detail: detail.to_string(),
            perturbed,
        });
    }
    Ok(checks)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_embedded_artifact_parses() {
        for a in &MODELS {
            assert!(a.ir.contains("carvallo-ir 1"), "{}: no IR header", a.model);
            let checks = parse_checks(a.checks).unwrap_or_else(|e| panic!("{}: {e}", a.model));
            assert!(!checks.is_empty(), "{}: no checks", a.model);
        }
        assert_eq!(artifact("hoop").map(|a| a.model), Some("hoop"));
        assert!(artifact("tricycle").is_none());
    }

    #[test]
    fn malformed_lines_are_named() {
        assert_eq!(
            parse_checks("# c\n1\tid\tmaybe\ts\td\t\t-").unwrap_err(),
            "line 2: holds must be true or false, found \"maybe\""
        );
        assert_eq!(
            parse_checks("1\tid\ttrue\ts\td\tp\tyes").unwrap_err(),
            "line 1: perturbed_holds must be true or false, found \"yes\""
        );
        assert_eq!(
            parse_checks("1\tid").unwrap_err(),
            "line 1: expected 7 tab-separated fields, found 2"
        );
        let c = parse_checks("1\tid\ttrue\ts\td\tevery `R` scaled\tfalse\n2\tj\ttrue\ts\td\t\t-")
            .unwrap();
        assert_eq!(c[0].perturbed, Some(("every `R` scaled".to_string(), false)));
        assert_eq!(c[1].perturbed, None);
    }
}
