//! The renderers of the concordance: the aligned text table ([`text`]), its number-normalised
//! form for snapshots ([`normalise`]), JSON ([`json`]) and the Markdown report ([`markdown`]),
//! over the number format they share ([`number`]).

pub mod json;
pub mod markdown;
pub mod normalise;
pub mod number;
pub mod text;

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use crate::entry::{Derived, Entry, Memoir, Verdict};
    use crate::render::json::render_json;
    use crate::render::text::{format_significant, render_text};

    fn sample() -> Vec<Entry> {
        vec![
            Entry {
                falsification: None,
                section: "4".into(),
                quantity: "A / (mu R^2)".into(),
                memoir: Memoir::Number(1.5),
                derived: Derived::Number(1.5),
                rel_diff: Some(0.0),
                verdict: Verdict::Agrees,
                note: "coefficient of mu R^2".into(),
            },
            Entry {
                falsification: None,
                section: "14".into(),
                quantity: "x".into(),
                memoir: Memoir::Formula("n^2 + 1".into()),
                derived: Derived::Numbers(BTreeMap::from([("points".into(), 64.0)])),
                rel_diff: None,
                verdict: Verdict::MemoirError,
                note: String::new(),
            },
        ]
    }

    #[test]
    fn significant_digits() {
        assert_eq!(format_significant(1.5, 10), "1.5");
        assert_eq!(format_significant(0.24999999999999997, 10), "0.25");
        assert_eq!(format_significant(-123456.0, 3), "-1.23e5");
        assert_eq!(format_significant(2.5e-7, 4), "2.5e-7");
        assert_eq!(format_significant(0.0, 4), "0");
    }

    #[test]
    fn verdicts_serialise_as_kebab_case() {
        let all = [
            Verdict::Agrees,
            Verdict::Rounding,
            Verdict::MemoirError,
            Verdict::Ocr,
            Verdict::DerivationDiffers,
        ];
        for v in all {
            assert_eq!(serde_json::to_value(v).unwrap(), serde_json::json!(v.as_str()));
        }
    }

    #[test]
    fn json_has_the_seven_keys() {
        let json: serde_json::Value = serde_json::from_str(&render_json(&sample())).unwrap();
        let first = json.as_array().unwrap()[0].as_object().unwrap();
        let keys: Vec<&str> = first.keys().map(String::as_str).collect();
        let mut expected =
            vec!["section", "quantity", "memoir", "derived", "rel_diff", "verdict", "note"];
        expected.sort_unstable();
        assert_eq!(keys, expected);
        assert_eq!(first["memoir"], serde_json::json!(1.5));
        assert_eq!(json[1]["rel_diff"], serde_json::Value::Null);
        assert_eq!(json[1]["derived"]["points"], serde_json::json!(64.0));
    }

    #[test]
    fn text_table_is_aligned() {
        let text = render_text(&sample());
        let lines: Vec<&str> = text.lines().collect();
        assert!(lines[0].starts_with("n°  quantity"));
        let col = lines[0].chars().count() - "verdict".len();
        let row: Vec<char> = lines[2].chars().collect();
        assert_eq!((row[col - 1], row[col]), (' ', 'a'));
        assert!(lines[2].contains("agrees") && lines[3] == "    coefficient of mu R^2");
        assert!(lines[4].ends_with("memoir-error"));
    }
}
