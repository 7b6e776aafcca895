//! Tests of the Carvallo–Whipple bicycle: the parameter reader ([`params`]), the parameters by
//! name ([`design`]), the stability
//! windows and sweeps ([`stability`]), the uncertainty bands ([`uncertainty`]) and the
//! nonlinear equations against the linearisation ([`nonlinear`]) and against Basu-Mandal et
//! al.'s circular motion ([`basu_mandal`]), and the steady turns of the nonlinear model against
//! the linear static solution, simulations and Carvallo's own bicycle ([`steady_turn`]), and
//! the nonlinear model's singular configuration as the end of a run ([`singular`]; the leaning
//! rider's, [`lean_rider_singular`]).

mod basu_mandal;
mod bicycleparameters;
mod design;
mod jacobian;
mod lean_rider;
mod lean_rider_singular;
mod nonlinear;
mod params;
mod reader_fuzz;
mod singular;
mod stability;
mod state_rate;
mod steady_turn;
mod uncertainty;
