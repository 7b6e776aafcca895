//! The subcommands of the `carvallo` command line, one module each (`bench` and `sweep` are
//! still in [`crate::perf`]): a module parses its own argument list, the command's name first,
//! and returns the text to print. Which word selects which module, what the help says about it
//! and which usage it prints is the table [`crate::COMMANDS`].

pub mod accel;
pub mod eig;
pub mod kinematics;
pub mod report;
pub mod rest;
pub mod simulate;
pub mod turn;
pub mod window;
