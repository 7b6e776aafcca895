//! The memoir as a source: every formula the derivations are checked against is transcribed by
//! hand from the OCR text of the 1897 memoir (`seeds/000_04652cc3a540bf9e.txt` in the shared
//! material beside the workspace, French), one module per model (`derive::*::memoir`), with
//! the [`Printed`] shape and the `printed!` table macro defined here once.

use symbolica::atom::Atom;

use crate::cas::{expr, from_trig};

/// One printed formula.
#[derive(Clone, Copy, Debug)]
pub struct Printed {
    /// Identifier (the output name for those handed over as `memoir_*`).
    pub id: &'static str,
    /// Section number as printed in the table of contents.
    pub section: &'static str,
    /// The formula in symbolica syntax.
    pub text: &'static str,
}

impl Printed {
    /// The formula with $\sin\theta, \cos\theta$ as the derivation's polynomial stand-ins.
    pub fn atom(&self) -> Atom {
        from_trig(&expr(self.text))
    }

    /// The formula as printed, with `sin(theta)`, `cos(theta)`, `tan(theta)`.
    pub fn trig_atom(&self) -> Atom {
        expr(self.text)
    }
}

/// Declares one `pub const` [`Printed`] per `ID, "section", "formula";` line, and `ALL`, every
/// formula of the table in memoir order.
macro_rules! printed {
    ($($id:ident, $sec:expr, $text:expr;)*) => {
        $(
            #[doc = concat!("n° ", $sec, ": `", $text, "`.")]
            pub const $id: $crate::memoir::Printed = $crate::memoir::Printed { id: stringify!($id), section: $sec, text: $text };
        )*
        /// Every transcribed formula, in memoir order.
        pub const ALL: &[$crate::memoir::Printed] = &[$($id),*];
    };
}

pub(crate) use printed;
