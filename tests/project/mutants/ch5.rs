//! Chapter 5 mutants (to come).
