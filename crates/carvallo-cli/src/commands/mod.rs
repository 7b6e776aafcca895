//! The subcommands of the `carvallo` command line, one module each: it parses its own argument
//! list and returns the text to print. Which word selects which module, and the help that
//! lists them, is the table [`crate::COMMANDS`].

pub mod kinematics;
pub mod rest;
pub mod simulate;
pub mod turn;
pub mod window;
