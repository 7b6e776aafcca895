//! The subcommands of the `carvallo` command line, one module each (`bench` and `sweep` are
//! still in [`crate::perf`]): a module's `Args` are its options (parsed by clap), its `run`
//! returns the text to print. Which word selects which module and what the help says about it
//! is the command table `Command` of `main.rs`.

pub mod accel;
pub mod bode;
pub mod eig;
pub mod kinematics;
pub mod lean_rider;
pub mod parameters;
pub mod pendulum;
pub mod plot;
pub mod report;
pub mod response;
pub mod rest;
pub mod rolling;
pub mod simulate;
pub mod simulate_inputs;
pub mod statespace;
pub mod turn;
pub mod window;
