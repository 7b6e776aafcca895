//! The integration tests of the `carvallo` library in one binary (one link instead of one per
//! file), one module per model as in `src/`: [`hoop`], [`unicycle`], [`whipple`], [`bicycle`],
//! [`wheeled_pendulum`],
//! the state Jacobians of the hoop, the unicycle and the leaning rider ([`jacobians`]),
//! and the numerical [`stress`] tests that cross models.

mod bicycle;
mod hoop;
mod jacobians;
mod stress;
mod unicycle;
mod wheeled_pendulum;
mod whipple;
