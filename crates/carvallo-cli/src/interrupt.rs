//! Ctrl-C: the flag it sets, which the long commands (sweeps, simulations) poll to end early
//! with what they have done.

use std::sync::atomic::{AtomicBool, Ordering};

/// The flag that Ctrl-C sets (the handler is installed on the first call). Without a handler
/// (the platform refused it) Ctrl-C ends the process as usual.
pub(crate) fn interrupt_flag() -> &'static AtomicBool {
    static STOP: AtomicBool = AtomicBool::new(false);
    static HANDLER: std::sync::Once = std::sync::Once::new();
    HANDLER.call_once(|| {
        // An error only means Ctrl-C keeps its default effect.
        let _ = ctrlc::set_handler(|| STOP.store(true, Ordering::Relaxed));
    });
    &STOP
}
