//! Unit tests of the whole expansion on the fixture programs in `tests/fixtures/`.
