//! Span sweep (filled in next).
