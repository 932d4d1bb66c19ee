//! Helpers of the polymass example programs.

pub mod binary_stl;
