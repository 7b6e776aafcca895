//! Moving trihedra OIJK and OIjk and Grassmann products (memoir n° 1–3). Being written.
