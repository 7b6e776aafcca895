//! Property-based fuzzing of the parser: arbitrary strings, token soups and mutated valid
//! programs never make it panic, errors point inside the text, and whatever parses is valid and
//! round-trips through the printer.

mod common;

use carvallo_ir::Program;
use proptest::prelude::*;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The property every input must satisfy.
fn check(text: &str) {
    match Program::parse(text) {
        Ok(p) => {
            p.validate().unwrap();
            let printed = p.to_text();
            let q = Program::parse(&printed).unwrap();
            assert_eq!(q, p);
            assert_eq!(q.to_text(), printed);
        }
        Err(e) => {
            // The position is inside the text or one past the end of a line.
            let lines: Vec<&str> = text.split('\n').collect();
            assert!(e.line >= 1 && e.line <= lines.len(), "{e} for {text:?}");
            assert!(e.column >= 1 && e.column <= lines[e.line - 1].chars().count() + 1, "{e}");
            assert!(!e.message.is_empty() && !e.message.ends_with('.'));
        }
    }
}

/// Valid program texts to mutate (fixed seed), built once.
fn corpus() -> &'static [String] {
    static CORPUS: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();
    CORPUS.get_or_init(make_corpus)
}

fn make_corpus() -> Vec<String> {
    let mut rng = ChaCha8Rng::seed_from_u64(99);
    let mut v: Vec<String> =
        (0..16).map(|_| common::random_program(&mut rng, 12).to_text()).collect();
    v.push("# h\ncarvallo-ir 1\nmodel m\nparam R\ninput x\nlet c = const 1e-7\nlet a = powi x -2\noutput y = a\n".into());
    v
}

#[derive(Clone, Debug)]
enum Mutation {
    Delete(usize, usize),
    Insert(usize, String),
    DuplicateLine(usize),
    SwapLines(usize, usize),
    ReplaceToken(usize, String),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let token = prop_oneof![
        Just("=".to_string()),
        Just("let".to_string()),
        Just("output".to_string()),
        Just("param".to_string()),
        Just("powi".to_string()),
        Just("const".to_string()),
        Just("\n".to_string()),
        Just("#".to_string()),
        Just("99999999999999999999999".to_string()),
        Just("1e999".to_string()),
        Just("-0.0".to_string()),
        "[a-z_0-9é\\t .\\-+]{0,8}",
        any::<String>(),
    ];
    prop_oneof![
        (any::<usize>(), 0usize..20).prop_map(|(a, n)| Mutation::Delete(a, n)),
        (any::<usize>(), token.clone()).prop_map(|(a, s)| Mutation::Insert(a, s)),
        any::<usize>().prop_map(Mutation::DuplicateLine),
        (any::<usize>(), any::<usize>()).prop_map(|(a, b)| Mutation::SwapLines(a, b)),
        (any::<usize>(), token).prop_map(|(a, s)| Mutation::ReplaceToken(a, s)),
    ]
}

fn apply(text: &str, m: &Mutation) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut lines: Vec<String> = text.split('\n').map(str::to_string).collect();
    match m {
        Mutation::Delete(a, n) => {
            let a = a % (chars.len() + 1);
            let b = (a + n).min(chars.len());
            chars[..a].iter().chain(&chars[b..]).collect()
        }
        Mutation::Insert(a, s) => {
            let a = a % (chars.len() + 1);
            let mut out: String = chars[..a].iter().collect();
            out.push_str(s);
            out.extend(&chars[a..]);
            out
        }
        Mutation::DuplicateLine(a) => {
            let a = a % lines.len();
            let l = lines[a].clone();
            lines.insert(a, l);
            lines.join("\n")
        }
        Mutation::SwapLines(a, b) => {
            let n = lines.len();
            lines.swap(a % n, b % n);
            lines.join("\n")
        }
        Mutation::ReplaceToken(a, s) => {
            let mut tokens: Vec<String> = text.split(' ').map(str::to_string).collect();
            let n = tokens.len();
            tokens[a % n] = s.clone();
            tokens.join(" ")
        }
    }
}

// Case counts keep the whole file under a few seconds in debug builds.
proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_strings_do_not_panic(s in any::<String>()) {
        check(&s);
        check(&format!("carvallo-ir 1\nmodel m\n{s}"));
    }

    #[test]
    fn token_soup_does_not_panic(
        lines in proptest::collection::vec(
            "(let|param|input|output|model|carvallo-ir|=|const|add|neg|powi|atan2|[a-c]|1|-2|1e5|#| |\t){0,7}",
            0..8,
        )
    ) {
        let text = format!("carvallo-ir 1\nmodel m\n{}", lines.join("\n"));
        check(&text);
    }

    #[test]
    fn mutated_programs_do_not_panic(
        which in any::<usize>(),
        muts in proptest::collection::vec(mutation(), 1..4),
    ) {
        let corpus = corpus();
        let mut text = corpus[which % corpus.len()].clone();
        for m in &muts {
            text = apply(&text, m);
        }
        check(&text);
    }
}

#[test]
fn corpus_is_valid_and_mutations_break_it() {
    // Unmutated corpus entries parse; the fuzzer therefore starts from valid programs.
    for t in corpus() {
        check(t);
        assert!(Program::parse(t).is_ok());
    }
    // Deleting the `=` of the first `let` is an error at that spot.
    let t = "carvallo-ir 1\nmodel m\ninput x\nlet a = neg x\noutput y = a\n";
    let m = apply(t, &Mutation::Delete(t.find('=').unwrap(), 1));
    let e = Program::parse(&m).unwrap_err();
    assert_eq!((e.line, e.column), (4, 8));
    assert_eq!(e.message, "expected `=`, found \"neg\"");
}
