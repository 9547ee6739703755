//! raybook: the complete tracer of the workbook and its tools.

pub use ch00_toolkit as toolkit;
