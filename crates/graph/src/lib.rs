//! The dimension-generic node graph: opposite relation, untangling (OP1/OP2), gluing
#![forbid(unsafe_code)]
#![warn(missing_docs)]
