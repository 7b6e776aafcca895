//! `cargo xtask regen`: derive everything, write generated/ atomically, or check it. Being written.
