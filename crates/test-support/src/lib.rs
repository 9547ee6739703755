//! What the tests of several crates share, in one place: the tests'
//! random numbers ([`Rng`]), proptest strategies for shapes
//! ([`strategies`]), running a binary with its output closed
//! ([`closed_pipe`]), reading the bench's Markdown tables
//! ([`table_row`]), listing the files under a folder ([`files_under`]),
//! scenes of coincident surfaces ([`coincident`]) and comparing two
//! pictures pixel for pixel with a readable message ([`pictures`]).

pub mod closed_pipe;
pub mod coincident;
mod files;
pub mod pictures;
pub mod strategies;
pub mod table_row;

mod rng;

pub use files::files_under;
pub use rng::Rng;
