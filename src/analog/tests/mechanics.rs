//! The headlight servo's structures: inductors in series, inertias coupled by a gear.
