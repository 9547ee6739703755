//! What the tests of several crates share, in one place: the tests'
//! random numbers ([`Rng`]), proptest strategies for shapes
//! ([`strategies`]), running a binary with its output closed
//! ([`closed_pipe`]) and reading the bench's Markdown tables
//! ([`table_row`]).

pub mod closed_pipe;
pub mod strategies;
pub mod table_row;

mod rng;

pub use rng::Rng;
