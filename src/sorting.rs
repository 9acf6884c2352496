//! Stable sorting by a floating-point key (IEEE total order), through one
//! compiled sort. Each `sort_by` with a closure of its own compiles a sort
//! of its own, about 6 KB of WebAssembly; these helpers sort the keys'
//! indices with one, so that the browser's module keeps within its size
//! budget.

/// The indices of `keys` from the smallest key to the largest (total
/// order; equal keys in their order): a stable sort's permutation.
#[inline(never)]
pub fn order(keys: &[f64]) -> Vec<usize> {
    let mut index: Vec<usize> = (0..keys.len()).collect();
    index.sort_by(|&a, &b| keys[a].total_cmp(&keys[b]));
    index
}

/// Sorts `items` by `key`, smallest first, stably (as `sort_by` with
/// `total_cmp` of the keys). For largest first, negate the key: `-x` is
/// exactly the reverse of `x` in the total order.
pub fn sort_by_key<T>(items: &mut Vec<T>, key: impl Fn(&T) -> f64) {
    let keys: Vec<f64> = items.iter().map(key).collect();
    let mut slots: Vec<Option<T>> = items.drain(..).map(Some).collect();
    items.extend(order(&keys).into_iter().filter_map(|i| slots[i].take()));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The same permutation as the standard library's stable sort, for
    /// ties, signed zeros, infinities and NaN of either sign, smallest or
    /// largest first.
    #[test]
    fn sorts_as_the_standard_stable_sort() {
        let keys = [3.0, -0.0, f64::NAN, 0.0, 1.0, -f64::NAN, f64::INFINITY, 1.0, -2.5, f64::NEG_INFINITY, 0.0, 3.0];
        let tagged: Vec<(f64, usize)> = keys.iter().copied().zip(0..).collect();
        let mut ours = tagged.clone();
        sort_by_key(&mut ours, |t| t.0);
        let mut std = tagged.clone();
        std.sort_by(|a, b| a.0.total_cmp(&b.0));
        assert_eq!(ours.iter().map(|t| t.1).collect::<Vec<_>>(), std.iter().map(|t| t.1).collect::<Vec<_>>());
        let mut ours = tagged.clone();
        sort_by_key(&mut ours, |t| -t.0);
        let mut std = tagged;
        std.sort_by(|a, b| b.0.total_cmp(&a.0));
        assert_eq!(ours.iter().map(|t| t.1).collect::<Vec<_>>(), std.iter().map(|t| t.1).collect::<Vec<_>>());
    }
}
