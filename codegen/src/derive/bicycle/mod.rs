//! Carvallo's bicycle (memoir Part II): the geometry of the front wheel's contact (ch. I,
//! n° 43–58), the kinematics and rest equilibrium (ch. II, n° 59–69), the steady states and
//! the stability with hands (ch. IV, n° 79–106) and the straight running without hands (ch. V,
//! n° 107–124).

pub mod geometry;
pub mod kinematics;
pub mod steady;
pub mod straight;
