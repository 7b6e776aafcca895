//! The C peer of `carvallo bench`: the same straight-line program as a generated scene, printed
//! as C, compiled by the system C compiler and timed by itself.
//!
//! [`c_source`] prints a [`Program`] as one C function `kernel(const double *in, double *out)`
//! (one `const double` per SSA instruction, the same operations in the same order: `powi` as
//! repeated multiplication by squaring, which is what Rust's `f64::powi` computes, the other
//! operations as C's operators and `<math.h>` functions) and a `main` that reads the arguments
//! from standard input, prints the outputs with 17 significant digits and then times its own
//! loop of calls: the smallest of five means, each over calls lasting at least a given time,
//! with compiler barriers around every call so that nothing is hoisted out of the loop (the
//! counterpart of `std::hint::black_box` on the Rust side).
//!
//! [`run`] writes the source to a temporary directory, compiles it with `cc -O2` (or `$CC`), runs
//! it and returns its outputs and its time per call. Without a C compiler it returns
//! [`PeerError::NoCompiler`] and `carvallo bench` prints the row as skipped.

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::PathBuf;
use std::process::{Command, Stdio};

use carvallo::ir::{Op, Program, Value};

/// Why the C peer could not be measured.
#[derive(Debug)]
pub enum PeerError {
    /// No C compiler could be started.
    NoCompiler {
        /// The command tried.
        cc: String,
    },
    /// The compiler, the program or its output failed.
    Failed {
        /// What went wrong.
        what: String,
    },
}

impl std::fmt::Display for PeerError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            PeerError::NoCompiler { cc } => write!(f, "skipped: no C compiler (`{cc}` not found)"),
            PeerError::Failed { what } => write!(f, "C peer failed: {what}"),
        }
    }
}

impl std::error::Error for PeerError {}

/// The C spelling of `value`: `a[k]` locals for the arguments, `t[k]` for instructions.
fn c_name(p: &Program, v: Value) -> String {
    match v {
        Value::Param(i) => format!("a{i}"),
        Value::Input(i) => format!("a{}", p.params.len() + i as usize),
        Value::Inst(i) => format!("t{i}"),
    }
}

/// A finite `f64` as a C literal that reads back to the same bits.
fn c_float(x: f64) -> String {
    if x.is_nan() {
        "NAN".into()
    } else if x.is_infinite() {
        if x > 0.0 {
            "INFINITY".into()
        } else {
            "(-INFINITY)".into()
        }
    } else {
        format!("({x:e})")
    }
}

/// `x^k` as the multiplications of Rust's `f64::powi` (compiler-rt's `__powidf2`: binary
/// exponentiation, starting from 1 and multiplying the running square in for every set bit,
/// then one division for a negative exponent). The square chain is emitted as locals named
/// `{base}_s{j}`.
fn c_powi(out: &mut String, name: &str, x: &str, k: i32) {
    let n = k.unsigned_abs();
    let mut acc: Option<String> = None;
    let mut square = x.to_string();
    let mut bits = n;
    let mut j = 0;
    let mut body = String::new();
    loop {
        if bits & 1 == 1 {
            acc = Some(match acc {
                // __powidf2 starts from r = 1 and computes r *= a: 1 * a is exact.
                None => square.clone(),
                Some(a) => {
                    let t = format!("{name}_r{j}");
                    let _ = writeln!(body, "    const double {t} = {a} * {square};");
                    t
                }
            });
        }
        bits >>= 1;
        if bits == 0 {
            break;
        }
        let s = format!("{name}_s{j}");
        let _ = writeln!(body, "    const double {s} = {square} * {square};");
        square = s;
        j += 1;
    }
    out.push_str(&body);
    let value = acc.unwrap_or_else(|| "1.0".into());
    if k < 0 {
        let _ = writeln!(out, "    const double {name} = 1.0 / {value};");
    } else {
        let _ = writeln!(out, "    const double {name} = {value};");
    }
}

/// `p` as a C translation unit: `kernel` and a timing `main` (see the [module docs](self)).
pub fn c_source(p: &Program) -> String {
    let n_args = p.params.len() + p.inputs.len();
    let n_out = p.outputs.len();
    let mut s = String::new();
    let _ = writeln!(
        s,
        "/* Model `{}`: {} operations, {} arguments, {} outputs; written by carvallo bench. */",
        p.model,
        p.op_count().total,
        n_args,
        n_out
    );
    s.push_str("#include <math.h>\n#include <stdio.h>\n#include <stdlib.h>\n#include <time.h>\n\n");
    s.push_str(
        "__attribute__((noinline)) static void kernel(const double *restrict in, \
         double *restrict out) {\n",
    );
    for k in 0..n_args {
        let _ = writeln!(s, "    const double a{k} = in[{k}];");
    }
    for (i, inst) in p.insts.iter().enumerate() {
        let t = format!("t{i}");
        let g = |v: Value| c_name(p, v);
        let rhs = match inst.op {
            Op::Const(c) => c_float(c),
            Op::Neg(a) => format!("-{}", g(a)),
            Op::Add(a, b) => format!("{} + {}", g(a), g(b)),
            Op::Sub(a, b) => format!("{} - {}", g(a), g(b)),
            Op::Mul(a, b) => format!("{} * {}", g(a), g(b)),
            Op::Div(a, b) => format!("{} / {}", g(a), g(b)),
            Op::Powi(a, k) => {
                c_powi(&mut s, &t, &g(a), k);
                continue;
            }
            Op::Sqrt(a) => format!("sqrt({})", g(a)),
            Op::Sin(a) => format!("sin({})", g(a)),
            Op::Cos(a) => format!("cos({})", g(a)),
            Op::Tan(a) => format!("tan({})", g(a)),
            Op::Atan2(a, b) => format!("atan2({}, {})", g(a), g(b)),
        };
        let _ = writeln!(s, "    const double {t} = {rhs};");
    }
    for (k, o) in p.outputs.iter().enumerate() {
        let _ = writeln!(s, "    out[{k}] = {};", c_name(p, o.value));
    }
    s.push_str("}\n\n");
    let _ = write!(
        s,
        r#"static double now(void) {{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}}

/* stdin: {n_args} arguments, then the minimum seconds of the timing.
   stdout: {n_out} outputs, then "ns" and the nanoseconds per call. */
int main(void) {{
    double in[{n_args} + 1], out[{n_out} + 1], min_time;
    for (int i = 0; i < {n_args}; i++)
        if (scanf("%lf", &in[i]) != 1) return 2;
    if (scanf("%lf", &min_time) != 1) return 2;
    kernel(in, out);
    for (int k = 0; k < {n_out}; k++) printf("%.17g\n", out[k]);
    double slice = min_time / 5.0, best = INFINITY;
    long n = 1;
    int rounds = 0;
    while (rounds < 5) {{
        double t0 = now();
        for (long r = 0; r < n; r++) {{
            __asm__ volatile("" : : "r"(in), "r"(out) : "memory");
            kernel(in, out);
            __asm__ volatile("" : : "r"(in), "r"(out) : "memory");
        }}
        double dt = now() - t0;
        if (dt >= slice) {{
            if (dt * 1e9 / (double)n < best) best = dt * 1e9 / (double)n;
            rounds++;
        }} else if (dt <= 0.0) {{
            n *= 16;
        }} else {{
            double f = 1.2 * slice / dt;
            n = (long)((double)n * (f < 16.0 ? f : 16.0)) + 1;
        }}
    }}
    printf("ns %.3f\n", best);
    return 0;
}}
"#
    );
    s
}

/// What the C peer measured.
#[derive(Clone, Debug, PartialEq)]
pub struct PeerRun {
    /// The outputs of one call, in the order of the program's outputs.
    pub outputs: Vec<f64>,
    /// Nanoseconds per call (the smallest of five means).
    pub ns: f64,
    /// The compile command, for the notes.
    pub command: String,
}

/// A fresh directory for the C files of this process.
fn work_dir(tag: &str) -> Result<PathBuf, PeerError> {
    let dir = std::env::temp_dir().join(format!("carvallo-peer-{}-{tag}", std::process::id()));
    std::fs::create_dir_all(&dir)
        .map_err(|e| PeerError::Failed { what: format!("cannot create {}: {e}", dir.display()) })?;
    Ok(dir)
}

/// Compiles `p` with `$CC` (default `cc`) `-O2`, runs it on `args` (parameters then inputs) and
/// returns its outputs and time per call, measured over at least `min_time` seconds.
///
/// # Errors
/// [`PeerError::NoCompiler`] when the compiler cannot be started, [`PeerError::Failed`] when it
/// or the program fails or prints something unexpected.
pub fn run(p: &Program, args: &[f64], min_time: f64, tag: &str) -> Result<PeerRun, PeerError> {
    let fail = |what: String| PeerError::Failed { what };
    if args.len() != p.params.len() + p.inputs.len() {
        return Err(fail(format!(
            "{} arguments for a program of {}",
            args.len(),
            p.params.len() + p.inputs.len()
        )));
    }
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let dir = work_dir(tag)?;
    let src = dir.join("kernel.c");
    let exe = dir.join("kernel");
    std::fs::write(&src, c_source(p))
        .map_err(|e| fail(format!("cannot write {}: {e}", src.display())))?;
    let command = format!("{cc} -O2 kernel.c -lm");
    let compiled =
        Command::new(&cc).arg("-O2").arg("-o").arg(&exe).arg(&src).arg("-lm").output().map_err(
            |e| match e.kind() {
                std::io::ErrorKind::NotFound => PeerError::NoCompiler { cc: cc.clone() },
                _ => fail(format!("cannot start `{cc}`: {e}")),
            },
        );
    let result = compiled.and_then(|out| {
        if !out.status.success() {
            let err = String::from_utf8_lossy(&out.stderr);
            return Err(fail(format!("`{command}` failed: {}", err.lines().next().unwrap_or(""))));
        }
        let mut child = Command::new(&exe)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .map_err(|e| fail(format!("cannot run the compiled kernel: {e}")))?;
        let mut input = String::new();
        for a in args {
            let _ = writeln!(input, "{a:?}");
        }
        let _ = writeln!(input, "{min_time:?}");
        if let Some(mut stdin) = child.stdin.take() {
            stdin
                .write_all(input.as_bytes())
                .map_err(|e| fail(format!("cannot write to the kernel: {e}")))?;
        }
        let out = child.wait_with_output().map_err(|e| fail(format!("the kernel failed: {e}")))?;
        if !out.status.success() {
            return Err(fail(format!("the kernel exited with {}", out.status)));
        }
        parse_output(&String::from_utf8_lossy(&out.stdout), p.outputs.len())
            .map(|(outputs, ns)| PeerRun { outputs, ns, command: command.clone() })
            .ok_or_else(|| fail("unexpected output of the kernel".into()))
    });
    let _ = std::fs::remove_dir_all(&dir);
    result
}

/// The outputs and the `ns` line the kernel prints.
fn parse_output(text: &str, n_out: usize) -> Option<(Vec<f64>, f64)> {
    let mut lines = text.lines();
    let outputs: Vec<f64> =
        lines.by_ref().take(n_out).map(|l| l.trim().parse().ok()).collect::<Option<_>>()?;
    if outputs.len() != n_out {
        return None;
    }
    let ns = lines.next()?.strip_prefix("ns ")?.trim().parse().ok()?;
    Some((outputs, ns))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn program() -> Program {
        Program::parse(
            "carvallo-ir 1\nmodel demo\nparam R\ninput x\nlet t0 = sin x\nlet t1 = powi t0 5\n\
             let t2 = powi R -3\nlet c0 = const 0.1\nlet t3 = mul t1 t2\nlet t4 = add t3 c0\n\
             output y = t4\noutput z = t2\n",
        )
        .unwrap()
    }

    #[test]
    fn powi_follows_binary_exponentiation() {
        let mut s = String::new();
        c_powi(&mut s, "t", "x", 5);
        assert_eq!(
            s,
            "    const double t_s0 = x * x;\n    const double t_s1 = t_s0 * t_s0;\n    \
             const double t_r2 = x * t_s1;\n    const double t = t_r2;\n"
        );
        let mut s = String::new();
        c_powi(&mut s, "t", "x", -2);
        assert_eq!(s, "    const double t_s0 = x * x;\n    const double t = 1.0 / t_s0;\n");
    }

    #[test]
    fn source_names_every_value_and_reads_constants_back_exactly() {
        let src = c_source(&program());
        assert!(src.contains("const double t0 = sin(a1);"), "{src}");
        // C locals are numbered by instruction (the constant `c0` is instruction 3).
        assert!(src.contains("const double t3 = (1e-1);"), "{src}");
        assert!(src.contains("const double t4 = t1 * t2;"), "{src}");
        assert!(src.contains("const double t2_r1 = a0 * t2_s0;"), "{src}");
        assert!(src.contains("const double t2 = 1.0 / t2_r1;"), "{src}");
        assert!(src.contains("out[1] = t2;"), "{src}");
        assert_eq!(c_float(0.1), "(1e-1)");
        assert_eq!("1e-1".parse::<f64>().unwrap(), 0.1);
    }

    /// Where `cc` exists, the compiled kernel reproduces the interpreter to the last bit on
    /// this small program (the bench compares the big ones to 1e-12).
    #[test]
    fn compiled_kernel_agrees_with_the_interpreter() {
        let p = program();
        let args = [1.3, 0.7];
        let want = p.eval_f64(&args[..1], &args[1..]).unwrap();
        match run(&p, &args, 0.001, "test") {
            Ok(r) => assert_eq!(r.outputs, want),
            Err(PeerError::NoCompiler { cc }) => eprintln!("no C compiler `{cc}`: not checked"),
            Err(e) => panic!("{e}"),
        }
    }

    #[test]
    fn output_parsing_rejects_short_output() {
        assert_eq!(parse_output("1\n2\nns 3.5\n", 2), Some((vec![1.0, 2.0], 3.5)));
        assert_eq!(parse_output("1\nns 3.5\n", 2), None);
        assert_eq!(parse_output("1\n2\n", 2), None);
    }
}
