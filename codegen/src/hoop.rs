//! The rolling hoop (memoir Part I, ch. I). Being written.
