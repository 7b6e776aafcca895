//! Tests of Carvallo's bicycle (memoir Part II), one module per module of `src/bicycle/`.

mod geometry;
mod kinematics;
mod rest;
mod straight;
mod turn;
