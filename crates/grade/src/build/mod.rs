//! Building in a copy: cargo with a small environment, confined to its
//! place (`build/cargo.rs`), the build artefacts every student shares, copied
//! into their own build folder (`build/share.rs`), and the digest that names
//! what was built from what.

pub mod cargo;
pub mod digest;
pub mod share;
