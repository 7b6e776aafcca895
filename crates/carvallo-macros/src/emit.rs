//! Writes the Rust module of a validated [`Scene`].
//!
//! The evaluator is the specialised program printed as flat SSA: one `let` per instruction,
//! named after the IR value, using only `f64` arithmetic and the `f64` methods `sqrt`, `sin`,
//! `cos`, `tan`, `atan2` and `powi`. Constants are bound once per function as `f64` literals in
//! Rust's shortest round-trip form, so the emitted value is the IR's value bit for bit.
//!
//! Programs with more than `max_fn_ops` operations are cut, in program order, into chunks of at
//! most that many operations. Each chunk becomes an `#[inline(never)]` function on one struct
//! (`Live`) of the values that cross chunks: it loads the values it needs from earlier chunks
//! (or the arguments) and stores the ones that later chunks or the outputs need, each value
//! stored once; `eval` then only glues the chunks together. This keeps every function small
//! enough for rustc, whose compile time grows badly with function size. (The former interface,
//! arrays of live values passed in and returned, copied every crossing value two or three times
//! and made the 2,498-op nonlinear bicycle 1.6 times slower than the same SSA compiled as C.)
//! A scene that raises `max_fn_ops` gets longer functions; beyond [`MAX_NESTED_LETS`]
//! operations their locals are declared in groups before they are assigned, since one `let`
//! per value nests one lexical scope per value and overflowed rustc's stack in debug builds.
//!
//! With `lanes: N` the same program is printed a second time inside a loop over `N` lanes
//! (`eval_lanes`, structure of arrays): the loop has a constant trip count and independent
//! iterations, so LLVM's loop vectorizer turns it into vector instructions (`mulpd`, `addpd`, ...;
//! a call such as `sin` stays one scalar call per lane), while every lane performs exactly the
//! scalar operations, so lane `j` is bit for bit the scalar result. (Writing each operation
//! over `[f64; N]` arrays instead was scalarised again by LLVM and gained nothing.)
//!
//! On x86, `eval_lanes` and the scalar `eval` of programs of at least [`AVX2_MIN_OPS`]
//! operations are printed twice: `*_portable` (the target's baseline, SSE2 on x86-64) and
//! `*_avx2` (`#[target_feature(enable = "avx2")]`), chosen at run time with
//! `is_x86_feature_detected!`. AVX2 gives the lanes four `f64` per instruction instead of two
//! and every function three-operand instructions (fewer register copies and spills: the 2,498-op
//! nonlinear bicycle went from 1.2 times the time of the same SSA compiled as C to 0.9 times).
//! FMA is not enabled and Rust never contracts `a * b + c`, so both variants compute the same
//! bits. Smaller scalar programs keep one inlinable `eval`: the check and the call cost more
//! than they save there (the 335-op bicycle matrices: 107 ns portable, 123 ns dispatched).

use std::collections::{BTreeSet, HashSet};

use carvallo_ir::{Op, Program, Value};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::{format_ident, quote};

use crate::scene::{rust_ident, Jacobian, Scene, RESERVED};

/// Programs of at least this many operations get an AVX2 variant of the scalar `eval`, chosen
/// at run time; smaller ones stay one inlinable function (the check and the call would cost
/// more than the shorter code saves).
const AVX2_MIN_OPS: usize = 1000;

/// Lints that flat generated arithmetic trips for no fault of the user.
fn allow_lints() -> TokenStream {
    quote! {
        #[allow(
            non_snake_case,
            clippy::approx_constant,
            clippy::excessive_precision,
            clippy::unreadable_literal,
            clippy::too_many_lines,
            clippy::many_single_char_names,
            clippy::suboptimal_flops,
            clippy::neg_multiply,
            clippy::let_and_return
        )]
    }
}

/// One compilation of the evaluators: the portable one (SSE2 on x86-64) or the one for CPUs with
/// AVX2, chosen at run time. Both print the same operations in the same order and neither
/// contracts a product and a sum into an FMA (Rust never does, and `avx2` does not enable
/// `fma`), so they return the same bits; AVX2 brings twice as wide vectors to `eval_lanes`
/// and three-operand instructions (fewer register copies) to both.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Variant {
    Portable,
    Avx2,
}

impl Variant {
    /// The suffix of the functions of this variant (`eval_avx2`, `part_0_avx2`).
    fn suffix(self) -> &'static str {
        match self {
            Variant::Portable => "portable",
            Variant::Avx2 => "avx2",
        }
    }

    /// The attributes of every function of this variant.
    fn attrs(self) -> TokenStream {
        match self {
            Variant::Portable => TokenStream::new(),
            Variant::Avx2 => quote! {
                #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
                #[target_feature(enable = "avx2")]
            },
        }
    }

    /// The name of helper `k` (`part`, `lanes_part`) of this variant.
    fn helper(self, base: &str, k: usize) -> Ident {
        match self {
            Variant::Portable => format_ident!("{}_{}", base, k),
            Variant::Avx2 => format_ident!("{}_{}_avx2", base, k),
        }
    }
}

/// The identifier of a struct field for the IR name `name` (validation has checked that there
/// is one; the positional fallback keeps this function total).
fn field(name: &str, index: usize) -> Ident {
    rust_ident(name, Span::call_site()).unwrap_or_else(|| format_ident!("field_{}", index))
}

/// A finite `f64` as an exact suffixed literal (`-1.5_f64`), non-finite ones as the `f64`
/// associated constants.
pub fn float(c: f64) -> TokenStream {
    if c.is_nan() {
        return quote!(f64::NAN);
    }
    if c.is_infinite() {
        return if c > 0.0 { quote!(f64::INFINITY) } else { quote!(f64::NEG_INFINITY) };
    }
    let magnitude = match format!("{:?}_f64", c.abs()).parse::<Literal>() {
        Ok(lit) => quote!(#lit),
        Err(_) => {
            let bits = Literal::u64_unsuffixed(c.abs().to_bits());
            quote!(f64::from_bits(#bits))
        }
    };
    if c.is_sign_negative() {
        quote!(-#magnitude)
    } else {
        magnitude
    }
}

/// An `i32` literal, with a separate minus sign.
fn int(k: i32) -> TokenStream {
    let lit = Literal::i64_unsuffixed(i64::from(k).abs());
    if k < 0 {
        quote!(-#lit)
    } else {
        quote!(#lit)
    }
}

/// The local variable of every value of the program.
struct Locals {
    params: Vec<Ident>,
    inputs: Vec<Ident>,
    insts: Vec<Ident>,
}

impl Locals {
    /// Locals named after the IR values; a name that is taken by a module item or cannot be an
    /// identifier gets `_` appended until it is free.
    fn new(p: &Program, parts: usize) -> Locals {
        let mut taken: HashSet<String> = RESERVED.iter().map(ToString::to_string).collect();
        taken.extend((0..parts).flat_map(|k| {
            [
                format!("part_{k}"),
                format!("lanes_part_{k}"),
                format!("part_{k}_avx2"),
                format!("lanes_part_{k}_avx2"),
            ]
        }));
        let mut local = |name: &str| {
            let mut candidate = name.to_string();
            loop {
                if !taken.contains(&candidate) {
                    if let Some(ident) = rust_ident(&candidate, Span::call_site()) {
                        taken.insert(candidate);
                        return ident;
                    }
                }
                candidate.push('_');
            }
        };
        Locals {
            params: p.params.iter().map(|n| local(n)).collect(),
            inputs: p.inputs.iter().map(|n| local(n)).collect(),
            insts: p.insts.iter().map(|i| local(&i.name)).collect(),
        }
    }

    fn get(&self, v: Value) -> &Ident {
        match v {
            Value::Param(i) => &self.params[i as usize],
            Value::Input(i) => &self.inputs[i as usize],
            Value::Inst(i) => &self.insts[i as usize],
        }
    }
}

/// The right-hand side of `let` for one operation.
fn op_expr(op: &Op, l: &Locals) -> TokenStream {
    match *op {
        Op::Const(c) => float(c),
        Op::Neg(a) => {
            let a = l.get(a);
            quote!(-#a)
        }
        Op::Add(a, b) => {
            let (a, b) = (l.get(a), l.get(b));
            quote!(#a + #b)
        }
        Op::Sub(a, b) => {
            let (a, b) = (l.get(a), l.get(b));
            quote!(#a - #b)
        }
        Op::Mul(a, b) => {
            let (a, b) = (l.get(a), l.get(b));
            quote!(#a * #b)
        }
        Op::Div(a, b) => {
            let (a, b) = (l.get(a), l.get(b));
            quote!(#a / #b)
        }
        Op::Powi(a, k) => {
            let (a, k) = (l.get(a), int(k));
            quote!(#a.powi(#k))
        }
        Op::Sqrt(a) => {
            let a = l.get(a);
            quote!(#a.sqrt())
        }
        Op::Sin(a) => {
            let a = l.get(a);
            quote!(#a.sin())
        }
        Op::Cos(a) => {
            let a = l.get(a);
            quote!(#a.cos())
        }
        Op::Tan(a) => {
            let a = l.get(a);
            quote!(#a.tan())
        }
        Op::Atan2(y, x) => {
            let (y, x) = (l.get(y), l.get(x));
            quote!(#y.atan2(#x))
        }
    }
}

/// Whether instruction `i` of `p` is a constant.
fn is_const(p: &Program, i: usize) -> bool {
    matches!(p.insts[i].op, Op::Const(_))
}

/// The instruction indices among the operands of `insts` and the values `extra`.
fn referenced(p: &Program, insts: &[usize], extra: impl Iterator<Item = Value>) -> BTreeSet<usize> {
    insts
        .iter()
        .flat_map(|&i| p.insts[i].op.operands())
        .chain(extra)
        .filter_map(|v| match v {
            Value::Inst(i) => Some(i as usize),
            _ => None,
        })
        .collect()
}

/// The most `let` bindings [`lets`] prints one after the other. Each `let` opens a lexical
/// scope nested in the previous one, and LLVM's DWARF writer recurses once per level when the
/// function has inlined calls (`sqrt`, `powi`): rustc 1.95 with line tables (the workspace's
/// debug profile) overflowed its stack on a function of 9,245 such `let`s. Longer runs, which
/// only a scene's raised `max_fn_ops` makes, declare their locals first, [`DECLARED_PER_LET`]
/// to a `let`, and assign them after: the same values, a few dozen nested scopes.
const MAX_NESTED_LETS: usize = crate::scene::DEFAULT_MAX_FN_OPS;

/// The locals one declaring `let` of [`lets`] names, beyond [`MAX_NESTED_LETS`].
const DECLARED_PER_LET: usize = 256;

/// `let` bindings of the instructions `insts`, in order; beyond [`MAX_NESTED_LETS`] of them,
/// declarations in groups (`let (t1, t2, ...,);`) then one assignment per instruction.
fn lets(p: &Program, l: &Locals, insts: &[usize]) -> TokenStream {
    if insts.len() > MAX_NESTED_LETS {
        let declarations = insts.chunks(DECLARED_PER_LET).map(|group| {
            let names = group.iter().map(|&i| &l.insts[i]);
            quote!(let (#(#names,)*);)
        });
        let assignments = insts.iter().map(|&i| {
            let (name, rhs) = (&l.insts[i], op_expr(&p.insts[i].op, l));
            quote!(#name = #rhs;)
        });
        return quote!(#(#declarations)* #(#assignments)*);
    }
    let lets = insts.iter().map(|&i| {
        let (name, rhs) = (&l.insts[i], op_expr(&p.insts[i].op, l));
        quote!(let #name = #rhs;)
    });
    quote!(#(#lets)*)
}

/// `let` bindings of the constants among the instructions `used`.
fn const_lets(p: &Program, l: &Locals, used: &BTreeSet<usize>) -> TokenStream {
    lets(p, l, &used.iter().copied().filter(|&i| is_const(p, i)).collect::<Vec<_>>())
}

/// The whole program as one function: the constants it uses, then every operation.
fn unsplit(p: &Program, l: &Locals) -> TokenStream {
    let work: Vec<usize> = (0..p.insts.len()).filter(|&i| !is_const(p, i)).collect();
    let consts = const_lets(p, l, &referenced(p, &work, p.outputs.iter().map(|o| o.value)));
    let ops = lets(p, l, &work);
    quote!(#consts #ops)
}

/// The values that cross the chunks of a split program, shared by the scalar evaluator and
/// `eval_lanes`: what each chunk loads (arguments, and results of other chunks) and what is
/// stored once in the struct of crossing values (everything some chunk loads, and the non-constant
/// results the outputs read).
struct Split {
    /// Per chunk, the values it reads that it does not compute itself (constants excluded).
    live_in: Vec<BTreeSet<Value>>,
    /// The values kept in the struct, in value order (its fields).
    stored: BTreeSet<Value>,
}

impl Split {
    fn new(p: &Program, chunks: &[Vec<usize>]) -> Split {
        let mut chunk_of = vec![usize::MAX; p.insts.len()];
        for (k, c) in chunks.iter().enumerate() {
            for &i in c {
                chunk_of[i] = k;
            }
        }
        let crosses = |v: &Value, k: usize| match *v {
            Value::Inst(j) => !is_const(p, j as usize) && chunk_of[j as usize] != k,
            _ => true,
        };
        let live_in: Vec<BTreeSet<Value>> = chunks
            .iter()
            .enumerate()
            .map(|(k, c)| {
                c.iter().flat_map(|&i| p.insts[i].op.operands()).filter(|v| crosses(v, k)).collect()
            })
            .collect();
        let mut stored: BTreeSet<Value> = live_in.iter().flatten().copied().collect();
        stored.extend(
            p.outputs
                .iter()
                .map(|o| o.value)
                .filter(|v| matches!(*v, Value::Inst(j) if !is_const(p, j as usize))),
        );
        Split { live_in, stored }
    }

    /// The locals of the struct's fields.
    fn fields<'a>(&self, l: &'a Locals) -> Vec<&'a Ident> {
        self.stored.iter().map(|&v| l.get(v)).collect()
    }

    /// The locals chunk `k` loads from the struct.
    fn loads<'a>(&self, k: usize, l: &'a Locals) -> Vec<&'a Ident> {
        self.live_in[k].iter().map(|&v| l.get(v)).collect()
    }

    /// The locals of the instructions of `chunk` that it stores into the struct.
    fn stores<'a>(&self, chunk: &[usize], l: &'a Locals) -> Vec<&'a Ident> {
        chunk
            .iter()
            .filter(|&&i| self.stored.contains(&Value::Inst(i as u32)))
            .map(|&i| &l.insts[i])
            .collect()
    }
}

/// The body of an evaluator after the arguments are bound (the outputs are then bound to
/// their locals), plus any helper functions and the struct of the values that cross them.
///
/// A single chunk is one flat function. Several chunks become `#[inline(never)]` functions
/// that share one struct of the values that cross chunks (arguments that later chunks read,
/// results that later chunks or the outputs read): every such value is stored once by the
/// chunk (or the glue) that makes it and loaded by the chunks that use it.
fn body(
    p: &Program,
    l: &Locals,
    max_fn_ops: usize,
    chunks: &[Vec<usize>],
    variant: Variant,
) -> (TokenStream, TokenStream) {
    let out_values = || p.outputs.iter().map(|o| o.value);
    if chunks.len() <= 1 {
        return (unsplit(p, l), TokenStream::new());
    }

    let split = Split::new(p, chunks);
    let stored = &split.stored;
    let fields = split.fields(l);
    let inits = stored.iter().map(|&v| {
        let f = l.get(v);
        match v {
            Value::Inst(_) => quote!(#f: 0.0_f64),
            _ => quote!(#f),
        }
    });
    let mut helpers = if variant == Variant::Portable {
        quote! {
            /// The values that cross the helper functions of one evaluation.
            struct Live { #(#fields: f64,)* }
        }
    } else {
        TokenStream::new()
    };
    let attrs = variant.attrs();
    let mut glue = quote!(let mut live = Live { #(#inits),* };);
    for (k, c) in chunks.iter().enumerate() {
        let (ins, outs) = (split.loads(k, l), split.stores(c, l));
        let (n_in, n_out) = (ins.len(), outs.len());
        let consts = const_lets(p, l, &referenced(p, c, std::iter::empty()));
        let ops = lets(p, l, c);
        let name = variant.helper("part", k);
        let doc = format!(
            " Operations {}..{} of the evaluation (at most {max_fn_ops} per function): reads {n_in} \
             earlier values from `live`, stores the {n_out} that later parts or the outputs use.",
            k * max_fn_ops,
            k * max_fn_ops + c.len(),
        );
        helpers.extend(quote! {
            #[doc = #doc]
            #[inline(never)]
            #attrs
            fn #name(live: &mut Live) {
                #(let #ins = live.#ins;)*
                #consts
                #ops
                #(live.#outs = #outs;)*
            }
        });
        glue.extend(quote!(#name(&mut live);));
    }
    let outs: Vec<&Ident> = stored
        .iter()
        .filter(|v| matches!(v, Value::Inst(_)))
        .map(|&v| l.get(v))
        .filter(|f| out_values().any(|o| l.get(o) == *f))
        .collect();
    glue.extend(quote!(#(let #outs = live.#outs;)*));
    let consts = const_lets(p, l, &referenced(p, &[], out_values()));
    (quote!(#glue #consts), helpers)
}

/// The body of `eval_lanes` (arguments `args`, result `out`) and its helpers: the scalar
/// program inside a loop over the `n` lanes, each value a local of one lane. The loop has a
/// constant trip count and no dependence between lanes, so the compiler's loop vectorizer turns
/// it into vector instructions (calls such as `sin` become one scalar call per lane: the same
/// bits). A split program becomes one such loop per helper, with the crossing values stored per
/// lane in the struct `LiveLanes`.
fn lanes_body(
    p: &Program,
    l: &Locals,
    max_fn_ops: usize,
    chunks: &[Vec<usize>],
    n: usize,
    variant: Variant,
) -> (TokenStream, TokenStream) {
    let n_lit = Literal::usize_unsuffixed(n);
    let n_outs = Literal::usize_unsuffixed(p.outputs.len());
    let arg_locals: Vec<&Ident> = l.params.iter().chain(&l.inputs).collect();
    let arg_index: Vec<Literal> = (0..arg_locals.len()).map(Literal::usize_unsuffixed).collect();
    let out_index: Vec<Literal> = (0..p.outputs.len()).map(Literal::usize_unsuffixed).collect();
    let out_values = || p.outputs.iter().map(|o| o.value);
    let out_locals: Vec<&Ident> = out_values().map(|v| l.get(v)).collect();
    if chunks.len() <= 1 {
        let lets = unsplit(p, l);
        let body = quote! {
            let mut out = [[0.0_f64; #n_lit]; #n_outs];
            for j in 0..#n_lit {
                #(let #arg_locals = args[#arg_index][j];)*
                #lets
                #(out[#out_index][j] = #out_locals;)*
            }
            out
        };
        return (body, TokenStream::new());
    }
    let split = Split::new(p, chunks);
    let fields = split.fields(l);
    let stored_args: Vec<(&Ident, Literal)> = arg_locals
        .iter()
        .zip(&arg_index)
        .filter(|(a, _)| fields.contains(a))
        .map(|(a, i)| (*a, i.clone()))
        .collect();
    let (sa, si): (Vec<&Ident>, Vec<Literal>) = stored_args.into_iter().unzip();
    let mut helpers = if variant == Variant::Portable {
        quote! {
            /// The values that cross the helper functions of one evaluation of [`eval_lanes`],
            /// one array of lanes each.
            struct LiveLanes { #(#fields: [f64; #n_lit],)* }
        }
    } else {
        TokenStream::new()
    };
    let attrs = variant.attrs();
    let mut glue = quote! {
        let mut live = LiveLanes { #(#fields: [0.0_f64; #n_lit]),* };
        for j in 0..#n_lit {
            #(live.#sa[j] = args[#si][j];)*
        }
    };
    for (k, c) in chunks.iter().enumerate() {
        let (ins, outs) = (split.loads(k, l), split.stores(c, l));
        let consts = const_lets(p, l, &referenced(p, c, std::iter::empty()));
        let ops = lets(p, l, c);
        let name = variant.helper("lanes_part", k);
        let doc = format!(
            " Operations {}..{} of [`eval_lanes`] (at most {max_fn_ops} per function), lane by lane.",
            k * max_fn_ops,
            k * max_fn_ops + c.len(),
        );
        helpers.extend(quote! {
            #[doc = #doc]
            #[inline(never)]
            #attrs
            fn #name(live: &mut LiveLanes) {
                for j in 0..#n_lit {
                    #(let #ins = live.#ins[j];)*
                    #consts
                    #ops
                    #(live.#outs[j] = #outs;)*
                }
            }
        });
        glue.extend(quote!(#name(&mut live);));
    }
    let out_exprs = out_values().map(|v| match v {
        Value::Inst(i) if is_const(p, i as usize) => match p.insts[i as usize].op {
            Op::Const(c) => float(c),
            _ => quote!(0.0_f64),
        },
        Value::Inst(_) => {
            let f = l.get(v);
            quote!(live.#f[j])
        }
        Value::Param(_) | Value::Input(_) => {
            let k = arg_locals.iter().position(|a| *a == l.get(v)).unwrap_or(0);
            let k = Literal::usize_unsuffixed(k);
            quote!(args[#k][j])
        }
    });
    glue.extend(quote! {
        let mut out = [[0.0_f64; #n_lit]; #n_outs];
        for j in 0..#n_lit {
            #(out[#out_index][j] = #out_exprs;)*
        }
        out
    });
    (glue, helpers)
}

/// `a`, `b` as "`a`, `b`" (or "none").
fn names<'a>(items: impl IntoIterator<Item = &'a String>) -> String {
    let v: Vec<String> = items.into_iter().map(|n| format!("`{n}`")).collect();
    if v.is_empty() {
        "none".to_string()
    } else {
        v.join(", ")
    }
}

/// The items of `jacobian: [...]`: the row and column names, the count of computed entries and
/// `jacobian`/`jacobian_array`, which arrange the derivative outputs as a dense matrix with
/// the structural zeros written as `0.0` (nothing is computed for them).
fn emit_jacobian(j: &Jacobian, out_fields: &[Ident], model: &str) -> TokenStream {
    let (m, k) = (j.of.len(), j.wrt.len());
    let (m_lit, k_lit) = (Literal::usize_unsuffixed(m), Literal::usize_unsuffixed(k));
    let n_outs = Literal::usize_unsuffixed(out_fields.len());
    let nonzeros = j.entries.iter().flatten().filter(|e| e.is_some()).count();
    let nonzeros_lit = Literal::usize_unsuffixed(nonzeros);
    let (of, wrt) = (&j.of, &j.wrt);
    let rows = j.entries.iter().map(|row| {
        let cells = row.iter().map(|e| match e {
            Some(i) => {
                let f = &out_fields[*i];
                quote!(out.#f)
            }
            None => quote!(0.0),
        });
        quote!([#(#cells),*])
    });
    let rows_array = j.entries.iter().map(|row| {
        let cells = row.iter().map(|e| match e {
            Some(i) => {
                let i = Literal::usize_unsuffixed(*i);
                quote!(out[#i])
            }
            None => quote!(0.0),
        });
        quote!([#(#cells),*])
    });
    let doc = format!(
        " The Jacobian of model `{model}`'s outputs [`JACOBIAN_OF`] with respect to \
         [`JACOBIAN_WRT`] at the point `out` was evaluated at: entry `[i][j]` is \
         d `JACOBIAN_OF[i]` / d `JACOBIAN_WRT[j]`, generated by forward-mode differentiation \
         of the model's program; the {} structural zeros of its {} entries are `0.0`, never \
         computed.",
        m * k - nonzeros,
        m * k
    );
    quote! {
        /// The outputs differentiated: the rows of [`jacobian`].
        pub const JACOBIAN_OF: [&str; #m_lit] = [#(#of),*];
        /// The inputs and parameters differentiated with respect to: the columns of
        /// [`jacobian`].
        pub const JACOBIAN_WRT: [&str; #k_lit] = [#(#wrt),*];
        /// The number of entries of [`jacobian`] the code computes; the others are
        /// structural zeros.
        pub const JACOBIAN_NONZEROS: usize = #nonzeros_lit;

        #[doc = #doc]
        #[inline]
        #[must_use]
        pub fn jacobian(out: &Out) -> [[f64; #k_lit]; #m_lit] {
            [#(#rows),*]
        }

        /// [`jacobian`] from the outputs of [`eval_array`].
        #[inline]
        #[must_use]
        pub fn jacobian_array(out: &[f64; #n_outs]) -> [[f64; #k_lit]; #m_lit] {
            [#(#rows_array),*]
        }
    }
}

/// The module of one scene.
pub fn emit(scene: &Scene) -> TokenStream {
    let p = &scene.program;
    let model = &scene.model;
    let scene_name = scene.name.to_string();
    let work: Vec<usize> = (0..p.insts.len()).filter(|&i| !is_const(p, i)).collect();
    let chunks: Vec<Vec<usize>> = work.chunks(scene.max_fn_ops).map(<[usize]>::to_vec).collect();
    let n_parts = if chunks.len() > 1 { chunks.len() } else { 0 };
    let l = Locals::new(p, n_parts);
    let op_count = p.op_count();
    let total = op_count.total;
    let total_lit = Literal::usize_unsuffixed(total);
    let by_op = op_count.by_op.iter().map(|(op, n)| {
        let n = Literal::usize_unsuffixed(*n);
        quote!((#op, #n))
    });
    let source_total = Literal::usize_unsuffixed(scene.source_op_count);

    let params = &p.params;
    let inputs = &p.inputs;
    let outputs: Vec<&String> = p.outputs.iter().map(|o| &o.name).collect();
    let fixed_names = scene.fixed.iter().map(|(n, _)| n);
    let fixed_values = scene.fixed.iter().map(|(_, v)| float(*v));
    let ir_path = scene.ir_path.to_string_lossy().into_owned();
    let ir_display = &scene.ir_display;

    // Structs.
    let arg_names: Vec<&String> = params.iter().chain(inputs).collect();
    let arg_fields: Vec<Ident> = arg_names.iter().enumerate().map(|(i, n)| field(n, i)).collect();
    let arg_docs = params
        .iter()
        .map(|n| format!(" Parameter `{n}` of model `{model}`."))
        .chain(inputs.iter().map(|n| format!(" Input `{n}` of model `{model}`.")));
    let arg_locals: Vec<&Ident> = l.params.iter().chain(&l.inputs).collect();
    let arg_pattern =
        arg_fields.iter().zip(&arg_locals).map(
            |(f, v)| {
                if f == *v {
                    quote!(#f)
                } else {
                    quote!(#f: #v)
                }
            },
        );
    let n_args = arg_fields.len();
    let out_fields: Vec<Ident> = outputs.iter().enumerate().map(|(i, n)| field(n, i)).collect();
    let out_docs = outputs.iter().map(|n| format!(" Output `{n}` of model `{model}`."));
    let out_values = p.outputs.iter().zip(&out_fields).map(|(o, f)| {
        let v = l.get(o.value);
        if f == v {
            quote!(#f)
        } else {
            quote!(#f: #v)
        }
    });
    let n_outs = out_fields.len();
    let (n_args_lit, n_outs_lit) =
        (Literal::usize_unsuffixed(n_args), Literal::usize_unsuffixed(n_outs));
    let arg_tmp: Vec<Ident> = (0..n_args).map(|i| format_ident!("v{}", i)).collect();
    let out_tmp: Vec<Ident> = (0..n_outs).map(|i| format_ident!("v{}", i)).collect();

    let jacobian = scene.jacobian.as_ref().map(|j| emit_jacobian(j, &out_fields, model));

    // Docs.
    let fixed_text = if scene.fixed.is_empty() {
        "none".to_string()
    } else {
        scene.fixed.iter().map(|(n, v)| format!("`{n}` = {v:?}")).collect::<Vec<_>>().join(", ")
    };
    let summary = format!(
        " Scene `{scene_name}` of model `{model}`, generated by `scene!` from `{ir_display}`:"
    );
    let details = [
        format!(" * fixed parameters (folded into the code): {fixed_text};"),
        format!(" * free parameters: {};", names(params.iter())),
        format!(" * inputs: {};", names(inputs.iter())),
        format!(" * outputs: {};", names(outputs.iter().copied())),
        format!(" * operations: {total} (the whole model program has {}).", scene.source_op_count),
    ];
    let has_doc = scene.attrs.iter().any(|a| a.path().is_ident("doc"));
    let separator = if has_doc { quote!(#[doc = ""]) } else { TokenStream::new() };
    let mod_doc = quote!(#separator #[doc = #summary] #[doc = ""] #(#[doc = #details])*);
    let eval_doc = [
        format!(" Evaluates the outputs of scene `{scene_name}` (model `{model}`)."),
        String::new(),
        format!(
            " Arguments ([`Args`]): free parameters {}; inputs {}.",
            names(params.iter()),
            names(inputs.iter())
        ),
        format!(" Fixed parameters: {fixed_text}."),
        format!(" Returns ([`Out`]): {}.", names(outputs.iter().copied())),
        String::new(),
        format!(" Straight-line `f64` code of {total} operations: no allocation, no panics."),
    ];
    let eval_array_doc = format!(
        " [`eval`] on arrays: arguments in the order of [`PARAMS`] then [`INPUTS`] ({}), outputs in \
         the order of [`OUTPUTS`] ({}).",
        names(arg_names.iter().copied()),
        names(outputs.iter().copied())
    );

    let arg_pattern: Vec<TokenStream> = arg_pattern.collect();
    let out_values: Vec<TokenStream> = out_values.collect();
    let scalar_dispatch = total >= AVX2_MIN_OPS;
    let mut scalar = TokenStream::new();
    let mut eval_body = TokenStream::new();
    for variant in [Variant::Portable, Variant::Avx2] {
        let (body, helpers) = body(p, &l, scene.max_fn_ops, &chunks, variant);
        if !scalar_dispatch {
            // One variant, the body of `eval` itself.
            eval_body = quote! {
                let Args { #(#arg_pattern),* } = *a;
                #body
                Out { #(#out_values),* }
            };
            scalar = helpers;
            break;
        }
        let name = format_ident!("eval_{}", variant.suffix());
        let attrs = variant.attrs();
        let doc = match variant {
            Variant::Portable => {
                " [`eval`] compiled for the baseline CPU of the target (SSE2 on x86-64)."
            }
            Variant::Avx2 => {
                " [`eval`] compiled with AVX2 (no FMA: the same bits as [`eval_portable`]); the \
                 caller must check that the CPU has AVX2, which [`eval`] does."
            }
        };
        scalar.extend(quote! {
            #[doc = #doc]
            #[inline]
            #[must_use]
            #attrs
            pub fn #name(a: &Args) -> Out {
                let Args { #(#arg_pattern),* } = *a;
                #body
                Out { #(#out_values),* }
            }

            #helpers
        });
        eval_body = quote! {
            #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
            {
                if ::std::is_x86_feature_detected!("avx2") {
                    // SAFETY: the CPU has AVX2, the only feature `eval_avx2` enables.
                    return unsafe { eval_avx2(a) };
                }
            }
            eval_portable(a)
        };
    }
    let lanes = scene.lanes.map(|n| {
        let n_lit = Literal::usize_unsuffixed(n);
        let mut variants = TokenStream::new();
        for variant in [Variant::Portable, Variant::Avx2] {
            let (lbody, lhelpers) = lanes_body(p, &l, scene.max_fn_ops, &chunks, n, variant);
            let name = format_ident!("eval_lanes_{}", variant.suffix());
            let attrs = variant.attrs();
            let doc = match variant {
                Variant::Portable => {
                    " [`eval_lanes`] compiled for the baseline CPU of the target (SSE2 on x86-64: \
                     two lanes per vector instruction)."
                }
                Variant::Avx2 => {
                    " [`eval_lanes`] compiled with AVX2 (four lanes per vector instruction, no \
                     FMA: the same bits as [`eval_lanes_portable`]); the caller must check that \
                     the CPU has AVX2, which [`eval_lanes`] does."
                }
            };
            variants.extend(quote! {
                #[doc = #doc]
                #[inline]
                #[must_use]
                #attrs
                pub fn #name(args: &[[f64; #n_lit]; #n_args_lit]) -> [[f64; #n_lit]; #n_outs_lit] {
                    #lbody
                }

                #lhelpers
            });
        }
        let doc = [
            format!(
                " [`eval`] on {n} points at once, structure of arrays: `args[k][j]` is argument `k` \
                 (the order of [`PARAMS`] then [`INPUTS`]) of point `j`, and the result's `[k][j]` \
                 output `k` (the order of [`OUTPUTS`]) of point `j`."
            ),
            String::new(),
            " Every lane performs the scalar operations of [`eval`] in the same order, so lane `j` \
             of the result equals `eval_array` of point `j` bit for bit; the compiler turns the \
             lanes into vector instructions, AVX2 ones ([`eval_lanes_avx2`]) when the CPU has \
             them (checked at run time), SSE2 ones otherwise ([`eval_lanes_portable`])."
                .to_string(),
        ];
        quote! {
            /// Number of points [`eval_lanes`] evaluates per call.
            pub const LANES: usize = #n_lit;

            #(#[doc = #doc])*
            #[inline]
            #[must_use]
            pub fn eval_lanes(args: &[[f64; #n_lit]; #n_args_lit]) -> [[f64; #n_lit]; #n_outs_lit] {
                #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
                {
                    if ::std::is_x86_feature_detected!("avx2") {
                        // SAFETY: the CPU has AVX2, the only feature `eval_lanes_avx2` enables.
                        return unsafe { eval_lanes_avx2(args) };
                    }
                }
                eval_lanes_portable(args)
            }

            #variants
        }
    });
    let allow = allow_lints();
    let attrs = &scene.attrs;
    let vis = &scene.vis;
    let name = &scene.name;

    quote! {
        #(#attrs)*
        #mod_doc
        #allow
        #vis mod #name {
            /// The model this scene evaluates.
            pub const MODEL: &str = #model;
            /// The free parameters (the model's parameters that are neither fixed nor unused),
            /// in the order of the fields of [`Args`].
            pub const PARAMS: &[&str] = &[#(#params),*];
            /// The inputs the outputs depend on, in the order of the fields of [`Args`] after
            /// the parameters.
            pub const INPUTS: &[&str] = &[#(#inputs),*];
            /// The names of the fields of [`Args`] in order: [`PARAMS`] then [`INPUTS`].
            pub const ARGS: [&str; #n_args_lit] = [#(#arg_names),*];
            /// The outputs, in the order of the fields of [`Out`].
            pub const OUTPUTS: &[&str] = &[#(#outputs),*];
            /// The fixed parameters and the values folded into the code.
            pub const FIXED: &[(&str, f64)] = &[#((#fixed_names, #fixed_values)),*];
            /// Number of floating-point operations of [`eval`] (constants not counted).
            pub const OP_COUNT: usize = #total_lit;
            /// [`OP_COUNT`] by operation, as `(mnemonic, count)` sorted by mnemonic.
            pub const OP_COUNT_BY_OP: &[(&str, usize)] = &[#(#by_op),*];
            /// Number of operations of the model's whole program, before fixing and pruning.
            pub const SOURCE_OP_COUNT: usize = #source_total;

            // Rebuild the calling crate when the IR file changes.
            const _: &str = ::core::include_str!(#ir_path);

            /// The arguments of [`eval`]: free parameters, then inputs.
            #[derive(
                ::core::clone::Clone,
                ::core::marker::Copy,
                ::core::fmt::Debug,
                ::core::cmp::PartialEq,
                ::core::default::Default
            )]
            pub struct Args {
                #(#[doc = #arg_docs] pub #arg_fields: f64,)*
            }

            impl Args {
                /// Number of fields.
                pub const LEN: usize = #n_args_lit;

                /// The arguments from an array in field order.
                #[must_use]
                pub const fn from_array(a: [f64; #n_args_lit]) -> Self {
                    let [#(#arg_tmp),*] = a;
                    Args { #(#arg_fields: #arg_tmp),* }
                }

                /// The arguments as an array in field order.
                #[must_use]
                pub const fn to_array(&self) -> [f64; #n_args_lit] {
                    [#(self.#arg_fields),*]
                }

                /// The arguments by name: each field is `value` of its name, called once per
                /// field in the order of [`ARGS`].
                #[must_use]
                pub fn from_fn(mut value: impl ::core::ops::FnMut(&str) -> f64) -> Self {
                    Args { #(#arg_fields: value(#arg_names)),* }
                }
            }

            /// The outputs of [`eval`].
            #[derive(
                ::core::clone::Clone,
                ::core::marker::Copy,
                ::core::fmt::Debug,
                ::core::cmp::PartialEq,
                ::core::default::Default
            )]
            pub struct Out {
                #(#[doc = #out_docs] pub #out_fields: f64,)*
            }

            impl Out {
                /// Number of fields.
                pub const LEN: usize = #n_outs_lit;

                /// The outputs from an array in field order.
                #[must_use]
                pub const fn from_array(a: [f64; #n_outs_lit]) -> Self {
                    let [#(#out_tmp),*] = a;
                    Out { #(#out_fields: #out_tmp),* }
                }

                /// The outputs as an array in field order.
                #[must_use]
                pub const fn to_array(&self) -> [f64; #n_outs_lit] {
                    [#(self.#out_fields),*]
                }
            }

            #(#[doc = #eval_doc])*
            #[inline]
            #[must_use]
            pub fn eval(a: &Args) -> Out {
                #eval_body
            }

            #[doc = #eval_array_doc]
            #[inline]
            #[must_use]
            pub fn eval_array(args: &[f64; #n_args_lit]) -> [f64; #n_outs_lit] {
                eval(&Args::from_array(*args)).to_array()
            }

            #scalar
            #lanes
            #jacobian
        }
    }
}

#[cfg(test)]
mod tests {
    use carvallo_ir::Builder;

    use super::*;

    /// A chain of `n` square roots of sums, each on the previous one.
    fn chain(n: usize) -> Program {
        let mut b = Builder::new("chain");
        let x = b.input("x");
        let mut v = x;
        for _ in 0..n {
            let s = b.add(v, x);
            v = b.sqrt(s);
        }
        b.output("y", v);
        b.finish()
    }

    /// The `let` statements of [`lets`] over every instruction of `p`, and its text.
    fn lets_of(p: &Program) -> (usize, String) {
        let l = Locals::new(p, 0);
        let all: Vec<usize> = (0..p.insts.len()).collect();
        let text = lets(p, &l, &all).to_string();
        (text.matches("let ").count(), text)
    }

    /// Up to [`MAX_NESTED_LETS`] instructions are one `let` each; beyond, the locals are
    /// declared 256 to a `let` and assigned after, in program order, to the same expressions.
    #[test]
    fn long_runs_declare_their_locals_in_groups() {
        let short = chain(MAX_NESTED_LETS / 2);
        let (n, text) = lets_of(&short);
        assert_eq!(n, short.insts.len());
        assert!(!text.contains("let ("), "{}", &text[..200]);

        let long = chain(MAX_NESTED_LETS);
        let n_insts = long.insts.len();
        assert!(n_insts > MAX_NESTED_LETS);
        let (n, text) = lets_of(&long);
        assert_eq!(n, n_insts.div_ceil(DECLARED_PER_LET));
        assert_eq!(text.matches("let (").count(), n);
        // The assignments after the declarations, one per instruction, in order.
        let assigned = text.split(';').filter(|s| !s.trim_start().starts_with("let")).count();
        assert_eq!(assigned - 1, n_insts, "a statement per instruction and the empty tail");
        let l = Locals::new(&long, 0);
        let (first, last) = (&l.insts[0], &l.insts[n_insts - 1]);
        let first_at = text.find(&format!("{first} =")).expect("first assigned");
        let last_at = text.find(&format!("{last} =")).expect("last assigned");
        assert!(first_at < last_at);
    }
}
