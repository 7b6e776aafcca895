//! Seeded sample points of the concordance: the one generator ([`Rng`], SplitMix64 from
//! [`carvallo::numerics::rng`]) from which every model's report draws its points, so that the
//! report is the same on every platform.

pub use carvallo::numerics::rng::SplitMix64 as Rng;
