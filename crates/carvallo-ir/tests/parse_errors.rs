//! Every kind of parse error, with its exact 1-based line and column and its message.

use carvallo_ir::{ParseError, Program};

const HEAD: &str = "carvallo-ir 1\nmodel m\n";

fn check(text: &str, line: usize, column: usize, message: &str) {
    match Program::parse(text) {
        Ok(p) => panic!("parsed {text:?} into {p:?}"),
        Err(e) => {
            assert_eq!(
                e,
                ParseError { line, column, message: message.to_string() },
                "input {text:?}"
            );
            assert_eq!(e.to_string(), format!("line {line}, column {column}: {message}"));
        }
    }
}

fn body(rest: &str) -> String {
    format!("{HEAD}{rest}")
}

#[test]
fn missing_and_bad_headers() {
    check("", 1, 1, "missing version line `carvallo-ir 1`");
    check("# only a comment\n\n", 3, 1, "missing version line `carvallo-ir 1`");
    check("carvallo-ir 1", 1, 14, "missing model line `model NAME`");
    check("carvallo-ir 1\n", 2, 1, "missing model line `model NAME`");
    check("model m\n", 1, 1, "expected the version line `carvallo-ir 1`, found \"model\"");
    check("carvallo-ir 2\n", 1, 13, "unsupported format version \"2\"");
    check("carvallo-ir\n", 1, 12, "expected the format version at the end of the line");
    check("carvallo-ir 1 x\n", 1, 15, "unexpected trailing token \"x\"");
    check(
        "carvallo-ir 1\nparam R\n",
        2,
        1,
        "expected the model line `model NAME`, found \"param\"",
    );
    check("carvallo-ir 1\nmodel\n", 2, 6, "expected the model name at the end of the line");
    check("carvallo-ir 1\nmodel 9m\n", 2, 7, "invalid name \"9m\"");
    check("carvallo-ir 1\nmodel m n\n", 2, 9, "unexpected trailing token \"n\"");
}

#[test]
fn duplicate_headers() {
    check(&body("carvallo-ir 1\n"), 3, 1, "duplicate version line");
    check(&body("param a\n  model m\n"), 4, 3, "duplicate model line");
}

#[test]
fn statements_and_order() {
    check(&body("parm a\n"), 3, 1, "unknown statement \"parm\"");
    check(
        &body("input x\nparam a\n"),
        4,
        1,
        "\"param\" line after \"input\" lines (order is param, input, let, output)",
    );
    check(
        &body("input x\nlet a = neg x\ninput y\n"),
        5,
        1,
        "\"input\" line after \"let\" lines (order is param, input, let, output)",
    );
    check(
        &body("input x\noutput y = x\nlet a = neg x\n"),
        5,
        1,
        "\"let\" line after \"output\" lines (order is param, input, let, output)",
    );
}

#[test]
fn names() {
    check(&body("param 1a\n"), 3, 7, "invalid name \"1a\"");
    check(&body("param a-b\n"), 3, 7, "invalid name \"a-b\"");
    check(&body("param été\n"), 3, 7, "invalid name \"été\"");
    check(&body("param\n"), 3, 6, "expected a parameter name at the end of the line");
    check(&body("input\t\n"), 3, 7, "expected an input name at the end of the line");
    check(&body("param a b\n"), 3, 9, "unexpected trailing token \"b\"");
    check(&body("input x\nlet 2 = neg x\n"), 4, 5, "invalid name \"2\"");
    check(&body("input x\noutput y.z = x\n"), 4, 8, "invalid name \"y.z\"");
    // Columns count characters, not bytes.
    check(&body("input x # é\nlet é = neg x\n"), 4, 5, "invalid name \"é\"");
    check(&body("input x\nlet a = neg x\r\n"), 4, 13, "invalid name \"x\\r\"");
}

#[test]
fn redefinition_and_undefined() {
    check(&body("param a\nparam a\n"), 4, 7, "redefinition of \"a\"");
    check(&body("param a\ninput a\n"), 4, 7, "redefinition of \"a\"");
    check(&body("input x\nlet x = neg x\n"), 4, 5, "redefinition of \"x\"");
    check(&body("input x\nlet a = neg x\nlet a = neg x\n"), 5, 5, "redefinition of \"a\"");
    check(&body("input x\nlet a = add x b\n"), 4, 15, "use of undefined value \"b\"");
    // Use before definition is an undefined value at the point of use.
    check(&body("input x\nlet a = neg b\nlet b = neg x\n"), 4, 13, "use of undefined value \"b\"");
    check(&body("input x\nlet a = neg a\n"), 4, 13, "use of undefined value \"a\"");
    check(&body("input x\noutput y = z\n"), 4, 12, "use of undefined value \"z\"");
    check(&body("input x\noutput y = x\noutput y = x\n"), 5, 8, "duplicate output \"y\"");
    check(&body("input x\noutput y = 1.0\n"), 4, 12, "invalid name \"1.0\"");
}

#[test]
fn let_syntax_and_arity() {
    check(&body("input x\nlet a\n"), 4, 6, "expected `=` at the end of the line");
    check(&body("input x\nlet a := neg x\n"), 4, 7, "expected `=`, found \":=\"");
    check(&body("input x\nlet a =\n"), 4, 8, "expected an operation at the end of the line");
    check(&body("input x\nlet a = exp x\n"), 4, 9, "unknown operation \"exp\"");
    check(&body("input x\nlet a = add x\n"), 4, 9, "operation add takes 2 arguments, found 1");
    check(&body("input x\nlet a = neg x x\n"), 4, 9, "operation neg takes 1 argument, found 2");
    check(&body("input x\nlet a = atan2\n"), 4, 9, "operation atan2 takes 2 arguments, found 0");
    check(&body("let a = const\n"), 3, 9, "operation const takes 1 argument, found 0");
    check(&body("let a = const 1 2\n"), 3, 9, "operation const takes 1 argument, found 2");
    check(&body("input x\noutput y\n"), 4, 9, "expected `=` at the end of the line");
    check(&body("input x\noutput y = x x\n"), 4, 14, "unexpected trailing token \"x\"");
    check(&body("input x\noutput y =\n"), 4, 11, "expected a value name at the end of the line");
}

#[test]
fn numbers() {
    check(&body("let a = const 1.2.3\n"), 3, 15, "invalid number \"1.2.3\"");
    check(&body("let a = const 0x10\n"), 3, 15, "invalid number \"0x10\"");
    check(&body("let a = const inf\n"), 3, 15, "non-finite constant \"inf\"");
    check(&body("let a = const NaN\n"), 3, 15, "non-finite constant \"NaN\"");
    check(&body("let a = const -1e400\n"), 3, 15, "non-finite constant \"-1e400\"");
    check(&body("input x\nlet a = powi x 2.5\n"), 4, 16, "invalid i32 exponent \"2.5\"");
    check(
        &body("input x\nlet a = powi x 2147483648\n"),
        4,
        16,
        "invalid i32 exponent \"2147483648\"",
    );
    check(
        &body("input x\nlet a = powi x 99999999999999999999999999999999999999999\n"),
        4,
        16,
        "invalid i32 exponent \"99999999999999999999999999999999999999999\"",
    );
    check(&body("input x\nlet a = powi 2 x\n"), 4, 14, "invalid name \"2\"");
    // Huge decimal constants are fine as long as they are finite.
    let p = Program::parse(&body(
        "let a = const 123456789012345678901234567890123456789012345678901234567890\n",
    ))
    .unwrap();
    assert_eq!(p.insts.len(), 1);
    let p = Program::parse(&body("input x\nlet a = powi x -2147483648\n")).unwrap();
    assert_eq!(p.insts[0].op, carvallo_ir::Op::Powi(carvallo_ir::Value::Input(0), i32::MIN));
}

#[test]
fn comments_and_whitespace_are_not_errors() {
    let p = Program::parse(
        "  # indented comment\ncarvallo-ir 1 # v\n\t\nmodel m#x\ninput x\n#\noutput y = x #",
    )
    .unwrap();
    assert!(p.header.is_empty(), "an indented comment is not part of the header");
    assert_eq!(p.model, "m");
    assert_eq!(p.outputs.len(), 1);
}
