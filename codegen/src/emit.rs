//! Emission of a Derivation into IR, readable text and checks. Being written.
