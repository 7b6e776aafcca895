//! Every test of the derivation side in one binary: the symbolic derivations (one module per
//! model), the emission into IR, the regeneration of `generated/` (atomic writes, selection of
//! models) and the staleness of `generated/`.
//!
//! Without a license key symbolica allows one thread per process, and a second thread that
//! touches it aborts the process even after the first is done. So every test runs its body on
//! one shared worker thread ([`on_symbolica_thread`]), the only thread of this binary that ever
//! uses symbolica, and each model is derived once per run ([`derived`]), every model in the
//! order of `cargo xtask regen` before any test runs, however many tests look at it: the
//! staleness test renders the same derivations the model tests check.

mod bicycle_geometry;
mod bicycle_kinematics;
mod bicycle_steady;
mod bicycle_straight;
mod common;
mod emit;
mod engine;
mod engine_hoop;
mod engine_memoir;
mod engine_unicycle;
mod falsify;
mod hoop_checks;
mod hoop_discussion;
mod hoop_formulas;
mod hoop_frame;
mod hoop_numeric;
mod lean_rider;
mod regen_atomic;
mod regen_fresh;
mod unicycle;
mod wheeled_pendulum;
mod whipple_linear;
mod whipple_nonlinear;

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};
use std::sync::mpsc;
use std::sync::{Mutex, OnceLock};

use carvallo_codegen::derive::DERIVATIONS;
use carvallo_codegen::Derivation;

type Job = Box<dyn FnOnce() + Send>;

/// The symbols the derivations created that `derive::symbols::SYMBOLS` does not list, in
/// creation order (set by the worker once every model is derived).
static NEW_SYMBOLS: OnceLock<Vec<String>> = OnceLock::new();

/// Every symbol a derivation creates is declared in `derive::symbols::SYMBOLS`, so that
/// `cargo xtask regen MODEL` prints its terms in the order of a full regeneration.
#[test]
fn every_derivation_symbol_is_declared_in_order() {
    on_symbolica_thread(|| {
        let new = NEW_SYMBOLS.get().expect("set when the worker started");
        assert!(
            new.is_empty(),
            "append these symbols, in this order, at the end of codegen/src/derive/symbols.rs: {new:?}"
        );
        // The declared order is the creation order (nothing was created before it).
        let created = carvallo_codegen::cas::created_symbols();
        let known = carvallo_codegen::derive::symbols::SYMBOLS;
        assert_eq!(&created[..known.len()], known);
    });
}

/// Runs `body` on the single worker thread that owns all symbolica use of this test binary,
/// and re-raises its panic (a failed assertion) in the calling test.
pub fn on_symbolica_thread(body: fn()) {
    static WORKER: OnceLock<Mutex<mpsc::Sender<Job>>> = OnceLock::new();
    let worker = WORKER.get_or_init(|| {
        let (tx, rx) = mpsc::channel::<Job>();
        std::thread::spawn(move || {
            // Symbolica prints an expression's terms in the order its symbols were created in
            // the process, and some check details (written to `generated/*.checks.tsv`) are such
            // prints: derive every model first, in the order `cargo xtask regen` does, so that
            // every test sees the state the regeneration had (a derivation that fails is
            // reported by the tests that use it).
            carvallo_codegen::derive::declare_symbols();
            carvallo_codegen::emit::declare_placeholders();
            for (model, _) in DERIVATIONS {
                let _ = catch_unwind(|| derived(model));
            }
            let created = carvallo_codegen::cas::created_symbols();
            let known = carvallo_codegen::derive::symbols::SYMBOLS;
            let _ = NEW_SYMBOLS
                .set(created.into_iter().filter(|s| !known.contains(&s.as_str())).collect());
            for job in rx {
                job();
            }
        });
        Mutex::new(tx)
    });
    let (done_tx, done_rx) = mpsc::channel();
    let job: Job = Box::new(move || {
        let _ = done_tx.send(catch_unwind(AssertUnwindSafe(body)));
    });
    worker
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
        .send(job)
        .expect("the symbolica worker thread is running");
    if let Err(payload) = done_rx.recv().expect("the symbolica worker thread answers") {
        // The worker's own panic message went to whichever test's output the worker inherited:
        // say it again here, in the failing test.
        let message = payload
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| payload.downcast_ref::<&str>().copied());
        match message {
            Some(m) => panic!("{m}"),
            None => resume_unwind(payload),
        }
    }
}

/// The derivation of `model` (a name of `derive::DERIVATIONS`), derived once in this run (all of
/// them when the worker starts, in the table's order) and kept. Call it on the symbolica thread only (the cache is that
/// thread's): a panic names a failed derivation or an unknown model.
pub fn derived(model: &str) -> &'static Derivation {
    thread_local! {
        static CACHE: RefCell<BTreeMap<String, &'static Derivation>> =
            const { RefCell::new(BTreeMap::new()) };
    }
    if let Some(d) = CACHE.with(|c| c.borrow().get(model).copied()) {
        return d;
    }
    let derive = DERIVATIONS
        .iter()
        .find(|(name, _)| *name == model)
        .unwrap_or_else(|| panic!("no derivation named {model}"))
        .1;
    let start = std::time::Instant::now();
    let d = derive().unwrap_or_else(|e| panic!("the {model} derivation fails: {e:#}"));
    eprintln!("derived {model} in {:.1} s", start.elapsed().as_secs_f64());
    let d: &'static Derivation = Box::leak(Box::new(d));
    CACHE.with(|c| c.borrow_mut().insert(model.to_string(), d));
    d
}
