//! The one verdict policy over the whole concordance: what every entry's verdict may be given
//! what it compares (`carvallo_report::policy`). Each of the policy's seven rules is checked
//! on the entries (and the claim rule on the claims) with its thresholds written here, not
//! imported from the code under test, so that a rule loosened there fails here.

use carvallo_report::{all_claims, all_entries, Derived, Entry, Memoir, Verdict};

/// Failing symbolic checks that agree because the memoir itself says the statement fails
/// (n° 71: the unmodified Lagrange equations do not apply to Carvallo's parameters).
const FAILS_AS_THE_MEMOIR_SAYS: [(&str, &str); 3] = [
    ("71", "check lagrange_unmodified_nu"),
    ("71", "check lagrange_unmodified_sigma"),
    ("benchmark", "check plain_lagrange_delta"),
];

/// The policy's numbers, as its preamble states them (`report.md`).
const AGREEMENT: f64 = 1e-12;
const NUMERIC_CAP: f64 = 1e-4;
const SLIDE_RULE: f64 = 2e-3;
const UNIT_SLACK: f64 = 1e-9;

/// Words by which a note names the independent numerical route of the numeric rule.
const NUMERICAL_ROUTES: [&str; 6] =
    ["numerical", "differences", "Newton", "RK4", "eigen", "bisect"];

/// The declared order of an approximation the note states (`theta0^2 + gamma^2 = X`, or
/// `within N %` after "declares"), if any.
fn declared_order(note: &str) -> Option<f64> {
    if let Some((_, rest)) = note.split_once("theta0^2 + gamma^2 = ") {
        let num: String =
            rest.chars().take_while(|c| !c.is_whitespace() && *c != ')' && *c != ',').collect();
        return num.trim_end_matches(['.', ';']).parse().ok();
    }
    if note.contains("declare") {
        let (_, rest) = note.rsplit_once("within ")?;
        let num: String = rest.chars().take_while(|c| c.is_ascii_digit() || *c == '.').collect();
        if rest[num.len()..].trim_start().starts_with('%') {
            return num.parse::<f64>().ok().map(|p| p / 100.0);
        }
    }
    None
}

/// The unit of the last digit of `m` as its shortest decimal form writes it: an upper bound
/// of the unit the memoir printed (it may print trailing zeros, `1,20`, that `f64` drops).
fn repr_unit(m: f64) -> f64 {
    let s = format!("{m}");
    match s.split_once('.') {
        Some((_, d)) => 10f64.powi(-(d.len() as i32)),
        None => 1.0,
    }
}

fn value(d: &Derived) -> Option<f64> {
    match d {
        Derived::Number(x) => Some(*x),
        Derived::Numbers(m) => m.get("value").copied(),
    }
}

fn holds(e: &Entry) -> Option<f64> {
    match &e.derived {
        Derived::Numbers(m) => m.get("holds").copied(),
        Derived::Number(_) => None,
    }
}

/// Every violation of the seven rules, one line each.
fn violations(entries: &[Entry]) -> String {
    let mut wrong = String::new();
    let mut say = |e: &Entry, why: &str| {
        wrong.push_str(&format!(
            "n° {} {}: {} ({why})\n",
            e.section,
            e.quantity,
            e.verdict.as_str()
        ))
    };
    for e in entries {
        let v = e.verdict;
        let finding = matches!(v, Verdict::MemoirError | Verdict::Ocr | Verdict::DerivationDiffers);
        let order = declared_order(&e.note);
        let numeric_route = NUMERICAL_ROUTES.iter().any(|w| e.note.contains(w));
        // Rule 7, checks: a holding check agrees; a failing one never agrees, except the
        // three where the memoir says it fails, which must fail.
        if let Some(h) = holds(e) {
            let exception =
                FAILS_AS_THE_MEMOIR_SAYS.contains(&(e.section.as_str(), e.quantity.as_str()));
            match (h == 1.0, v, exception) {
                (true, Verdict::Agrees, false) => {}
                (false, Verdict::Agrees, true) => {}
                (false, Verdict::Agrees, false) => say(e, "rule 7: a failing check agrees"),
                (false, _, false) => {}
                (_, _, true) => say(e, "rule 7: expected to fail and agree"),
                (true, _, false) => say(e, "rule 7: a holding check does not agree"),
            }
            continue;
        }
        let Some(rel) = e.rel_diff else {
            // Rule 6, findings by attribution (no comparison): the note names the finding;
            // rule 5 covers the claims entered as rows (agrees when shown).
            if finding && e.note.is_empty() {
                say(e, "rule 6: a finding without its reason");
            }
            if v == Verdict::Rounding && order.is_none() {
                say(e, "rule 4: rounding without a declared approximation");
            }
            continue;
        };
        // Rule 2, numeric: an agreement looser than exact is a numerical route's, within
        // the cap 1e-4, and the note names the route.
        if v == Verdict::Agrees && rel > AGREEMENT {
            if rel > NUMERIC_CAP {
                say(e, &format!("rule 2: agrees at {rel:e}, above the cap"));
            }
            if !numeric_route {
                say(e, &format!("rule 2: agrees at {rel:e} with no numerical route named"));
            }
        }
        if rel.is_nan() && v == Verdict::Agrees {
            say(e, "an undefined difference agrees");
        }
        // Rule 4, approximations the memoir declares: rounding within the declared order,
        // beyond it a finding; exact only when within 1e-12.
        if let Some(order) = order {
            match v {
                Verdict::Rounding if rel > order || rel <= AGREEMENT => {
                    say(e, &format!("rule 4: rounding at {rel:e} for the order {order:e}"))
                }
                Verdict::Agrees if rel > AGREEMENT => say(e, "rule 4: an approximation agrees"),
                _ if finding && rel <= order => {
                    say(e, &format!("rule 4: a finding at {rel:e} within the order {order:e}"))
                }
                _ => {}
            }
            continue;
        }
        match &e.memoir {
            // Rule 1, formulas: agree within 1e-12 (or by rule 2), never rounding.
            Memoir::Formula(_) => {
                if v == Verdict::Rounding {
                    say(e, "rule 1: a formula is never rounding");
                }
                if rel <= AGREEMENT && v != Verdict::Agrees {
                    say(e, &format!("rule 1: {rel:e} does not agree"));
                }
                if v == Verdict::Agrees && rel > AGREEMENT && !numeric_route {
                    say(e, "rule 1: agrees beyond 1e-12");
                }
            }
            // Rule 3, printed numbers: rounding within one unit of the last printed digit or
            // 2e-3 relative; a finding only beyond 2e-3 (the printed unit itself, which the
            // stored number can hide, is bounded above by the shortest decimal form).
            Memoir::Number(m) => {
                // A difference of terms that cancel: within 2e-3 of the largest term.
                let terms = e.note.split_once("terms up to ").and_then(|(_, r)| {
                    r.split_whitespace().next().and_then(|x| x.parse::<f64>().ok())
                });
                let near = value(&e.derived).is_some_and(|d| {
                    (d - m).abs() <= repr_unit(*m) * (1.0 + UNIT_SLACK)
                        || terms.is_some_and(|t| (d - m).abs() <= SLIDE_RULE * t)
                });
                if v == Verdict::Rounding && !(rel <= SLIDE_RULE || near) {
                    say(e, &format!("rule 3: rounding at {rel:e}, beyond a unit and 2e-3"));
                }
                if v == Verdict::Rounding && rel <= AGREEMENT {
                    say(e, "rule 3: exact but rounding");
                }
                if finding && (rel <= SLIDE_RULE || terms.is_some_and(|_| near)) {
                    say(e, &format!("rule 3: a finding at {rel:e}, within a slide rule"));
                }
                if v == Verdict::Agrees && rel > AGREEMENT && !numeric_route {
                    say(e, "rule 3: a printed number agrees beyond 1e-12");
                }
            }
        }
    }
    wrong
}

#[test]
fn every_verdict_is_one_the_policy_allows() {
    let entries = all_entries();
    let wrong = violations(&entries);
    assert!(wrong.is_empty(), "verdicts outside the policy:\n{wrong}");
    // Each rule has entries to judge (a rule that no entry reaches checks nothing).
    let count = |f: &dyn Fn(&Entry) -> bool| entries.iter().filter(|e| f(e)).count();
    assert_eq!(count(&|e| holds(e) == Some(0.0) && e.verdict == Verdict::Agrees), 3);
    assert!(count(&|e| holds(e) == Some(1.0)) > 100);
    assert!(count(&|e| declared_order(&e.note).is_some() && e.verdict == Verdict::Rounding) >= 10);
    assert!(count(&|e| matches!(e.memoir, Memoir::Formula(_)) && e.rel_diff.is_some()) > 50);
    assert!(
        count(&|e| matches!(e.memoir, Memoir::Number(_)) && e.verdict == Verdict::Rounding) > 100
    );
    assert!(
        count(&|e| e.verdict == Verdict::Agrees && e.rel_diff.is_some_and(|r| r > AGREEMENT)) >= 3
    );
}

/// Rule 5, claims: a claim agrees when the derivation shows it, otherwise it is a finding;
/// it is `rounding` only when judged by the printed-number rule (its note says the bound is
/// a printed number rounded) and never carries an empty reading.
#[test]
fn every_claim_verdict_is_one_the_policy_allows() {
    let mut wrong = String::new();
    for c in all_claims() {
        if c.verdict == Verdict::Rounding
            && !(c.note.contains("rounded") || c.note.contains("relative"))
        {
            wrong.push_str(&format!("{}: rounding without the printed rule\n", c.id));
        }
        if c.verdict != Verdict::Agrees && c.note.is_empty() {
            wrong.push_str(&format!("{}: {} without a reason\n", c.id, c.verdict.as_str()));
        }
    }
    assert!(wrong.is_empty(), "claims outside the policy:\n{wrong}");
}

/// The rules fail on entries that break them: each perturbed entry below is taken from a
/// real one and must be reported.
#[test]
fn the_rules_catch_verdicts_outside_the_policy() {
    let entries = all_entries();
    let find =
        |f: &dyn Fn(&Entry) -> bool| entries.iter().find(|e| f(e)).expect("an entry").clone();
    let mut cases: Vec<(&str, Entry)> = Vec::new();
    // Rule 1: a formula within 1e-12 judged derivation-differs.
    let mut e = find(&|e| matches!(e.memoir, Memoir::Formula(_)) && e.rel_diff == Some(0.0));
    e.verdict = Verdict::DerivationDiffers;
    cases.push(("rule 1", e));
    // Rule 2: a numerical agreement at 2e-4, above the cap.
    let mut e =
        find(&|e| e.verdict == Verdict::Agrees && e.rel_diff.is_some_and(|r| r > AGREEMENT));
    e.rel_diff = Some(2e-4);
    cases.push(("rule 2", e));
    // Rule 3: a printed number judged memoir-error at 1e-3 relative.
    let mut e =
        find(&|e| matches!(e.memoir, Memoir::Number(_)) && e.verdict == Verdict::MemoirError);
    e.rel_diff = Some(1e-3);
    cases.push(("rule 3", e));
    // Rule 4: a declared approximation rounding beyond its order.
    let mut e = find(&|e| {
        declared_order(&e.note).is_some() && e.verdict == Verdict::Rounding && e.rel_diff.is_some()
    });
    e.rel_diff = Some(declared_order(&e.note).unwrap() * 1.01);
    cases.push(("rule 4", e));
    // Rule 6: a finding with no reason.
    let mut e = find(&|e| e.rel_diff.is_none() && holds(e).is_none() && e.verdict == Verdict::Ocr);
    e.note.clear();
    cases.push(("rule 6", e));
    // Rule 7: a failing check that agrees, not one of the three.
    let mut e = find(&|e| holds(e) == Some(0.0) && e.verdict == Verdict::MemoirError);
    e.verdict = Verdict::Agrees;
    cases.push(("rule 7", e));
    for (rule, e) in cases {
        let wrong = violations(std::slice::from_ref(&e));
        assert!(
            wrong.contains(rule),
            "{rule} not caught: {wrong:?} for n° {} {}",
            e.section,
            e.quantity
        );
    }
}
