//! Tests of the rolling hoop (memoir Part I, chapter I): the model's public API ([`model`]) and
//! the generated evaluators against the IR interpreter and the 256-bit evaluation
//! ([`evaluators`]).

mod evaluators;
mod model;
