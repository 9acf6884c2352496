//! What the overview scenes share: nothing beyond the other chapters' parameters.
