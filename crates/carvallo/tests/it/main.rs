//! The integration tests of the `carvallo` library in one binary (one link instead of one per
//! file), one module per model as in `src/`: [`hoop`], [`unicycle`], [`whipple`], [`bicycle`],
//! and the numerical [`stress`] tests that cross models.

mod bicycle;
mod hoop;
mod stress;
mod unicycle;
mod whipple;
