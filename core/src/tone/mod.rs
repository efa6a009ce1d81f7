//! Tone: from linear 12-bit intensity to display codes (seed 000).
