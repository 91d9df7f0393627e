//! placeholder: written by the optimizer helper
