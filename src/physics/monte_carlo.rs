//! Monte Carlo coagulation by the distribution method of Ormel & Spaans
//! (2008), as used in thesis Sect. 4.3: families of identical particles, each
//! made of w groups of 2^z particles; group collisions (4.20)/(4.25) with the
//! sequential-collision limit N_ε (4.21)–(4.24); zoom factors chosen per mass
//! decade (4.26) so that every decade holds about w* groups; merging of
//! families too small for their zoom factor (4.27).
//!
//! The engine is generic in the collision model ([`Model`]): the rate
//! coefficient of a pair and the outcome of one collision. This module
//! provides the analytic test kernels (constant, linear, product) with their
//! exact solutions; the porous-ice column of ch. 4 lives in
//! [`super::coagulation`].
//!
//! Cost per event: O(F) for F families. For every pair of families the rate
//! coefficient and the single-collision changes δm, δφ (which set N_ε) are
//! cached and recomputed only for families whose particles changed: the
//! model evaluates a family's whole row at once, in order of mass (so that
//! pairs in the same regime of the model follow each other), and the row
//! is written where the pair is read from (the row of the family computed
//! last). A pair's group rate (4.25) is w_i w_j times a unit rate
//! 2^{z_lo + N_ε} K/V that depends on the zoom factors but not on the group
//! counts, so an event that only changes group counts moves each partner's
//! sum Σ_j w_j u_ij by one multiply-add, and re-zooming recomputes unit
//! rates by cheap arithmetic. Event selection draws a family from w_i Σ_j w_j u_ij plus its
//! in-group rate, then its partner from that family's row.

use rand::{Rng, SeedableRng};

/// Mass and filling factor of a particle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// Mass (in the model's unit).
    pub mass: f64,
    /// Filling factor φ (1 for compact particles and the analytic kernels).
    pub filling: f64,
}

/// One family of identical particles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Family<P> {
    /// Particle mass (in the model's unit).
    pub mass: f64,
    /// Filling factor φ.
    pub filling: f64,
    /// Number of groups w (may be fractional, ≥ 1 while the family lives).
    pub groups: f64,
    /// Zoom factor z: each group holds 2^z particles.
    pub zoom: i32,
    /// Derived properties the model caches (stopping time, size, ...).
    pub props: P,
}

impl<P> Family<P> {
    /// Number of particles g = w 2^z.
    pub fn particles(&self) -> f64 {
        self.groups * exp2i(self.zoom)
    }

    /// The particle.
    pub fn body(&self) -> Body {
        Body { mass: self.mass, filling: self.filling }
    }
}

/// The outcome of one collision of a target with a projectile (the target is
/// the more massive particle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Collision {
    /// The particles merge into one of mass m_t + m_p whose filling factor
    /// is the target's plus `change`.
    Stick {
        /// φ_product − φ_target: a difference, so that a change far below the
        /// rounding of φ survives a sequence of many collisions (4.21).
        change: f64,
    },
    /// The target loses mass `loss` (its filling factor unchanged); the lost
    /// mass and the projectile leave as `count` fragments `fragment` (count
    /// may be fractional).
    Erode {
        /// Mass the target loses.
        loss: f64,
        /// One fragment.
        fragment: Body,
        /// Fragments per collision.
        count: f64,
    },
    /// Both particles break into `count` fragments `fragment`.
    Shatter {
        /// One fragment.
        fragment: Body,
        /// Fragments per collision.
        count: f64,
    },
    /// Nothing changes (bouncing).
    Bounce,
}

/// What one collision does to the more massive particle, as far as the
/// sequence limits (4.22)–(4.24) need it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Effect {
    /// The particles stick; the target's filling factor changes by `change`.
    Stick {
        /// φ_product − φ_target (as in [`Collision::Stick`]).
        change: f64,
    },
    /// The target loses this mass.
    Erode {
        /// Mass lost.
        loss: f64,
    },
    /// The target shatters.
    Shatter,
    /// Nothing happens.
    Bounce,
}

impl Effect {
    /// The effect of `collision`.
    pub fn of(collision: Collision) -> Effect {
        match collision {
            Collision::Stick { change } => Effect::Stick { change },
            Collision::Erode { loss, .. } => Effect::Erode { loss },
            Collision::Shatter { .. } => Effect::Shatter,
            Collision::Bounce => Effect::Bounce,
        }
    }
}

/// A collision model: rate coefficients and outcomes.
pub trait Model: Sync {
    /// Properties cached per family.
    type Props: Copy + Send + Sync + std::fmt::Debug;

    /// What the model keeps beside the families for its rows (e.g. their
    /// properties, one array per property), updated as they change
    /// ([`Model::set_lane`], [`Model::remove_lane`]); `()` for none.
    type Lanes: Default + Clone + Send + Sync + std::fmt::Debug;

    /// Family `i` is now `family` (`i` equal to the number of families
    /// before: a new family).
    fn set_lane(&self, _lanes: &mut Self::Lanes, _i: usize, _family: &Family<Self::Props>) {}

    /// Family `i` is removed, and the last family takes its index.
    fn remove_lane(&self, _lanes: &mut Self::Lanes, _i: usize) {}

    /// The cached properties of a particle.
    fn props(&self, body: Body) -> Self::Props;

    /// Rate coefficient K of a pair; the pair collision rate is K/V for the
    /// simulated volume (or column area) V.
    fn rate(&self, a: &Family<Self::Props>, b: &Family<Self::Props>) -> f64;

    /// The outcome of one collision; `target` is the more massive particle.
    fn collide(&self, target: &Family<Self::Props>, projectile: &Family<Self::Props>) -> Collision;

    /// The rate coefficient of a pair (as [`Model::rate`]) and what one
    /// collision does to the more massive particle (as [`Model::collide`]
    /// reduced to its mass change and filling factor after sticking; `None`
    /// when they bounce). Models override it to share work between the two.
    fn pair(&self, a: &Family<Self::Props>, b: &Family<Self::Props>) -> (f64, Effect) {
        let (t, p) = if a.mass >= b.mass { (a, b) } else { (b, a) };
        (self.rate(a, b), Effect::of(self.collide(t, p)))
    }

    /// The cached pair data ([`PairRule::data`] of [`Model::pair`]) of
    /// family `a` with each of `others[j]` for j in `which` into entry j of
    /// `out` (which holds `others.len()` entries; those not in `which` are
    /// left as they are); `lanes` are those of `others`. `which` lists the
    /// families by mass, so that pairs in the same regime of the model follow
    /// each other. Models override it to share work across a row; an
    /// override gives the same numbers to the last bit.
    fn pair_data_row(
        &self,
        _lanes: &Self::Lanes,
        a: &Family<Self::Props>,
        others: &[Family<Self::Props>],
        which: &[usize],
        rule: &PairRule,
        mut out: PairRow<'_>,
    ) {
        for &j in which {
            let b = &others[j];
            let (rate, effect) = self.pair(a, b);
            out.set(j, rule.data(a, b, rate, effect));
        }
    }

    /// The filling factor of a newly made particle after any compaction that
    /// acts on the particle as a whole (not per collision), e.g. by gas
    /// pressure or self-gravity; applied once to every product of a group
    /// event, after the sequence. By default none.
    fn compact(&self, body: Body) -> f64 {
        body.filling
    }
}

/// The analytic Smoluchowski kernels in units m₀ = 1, N₀ = 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Analytic {
    /// K = 1.
    Constant,
    /// K = m + m′.
    Linear,
    /// K = m m′ (gels at t = 1).
    Product,
}

impl Model for Analytic {
    type Props = ();
    type Lanes = ();

    fn props(&self, _: Body) -> Self::Props {}

    fn rate(&self, a: &Family<()>, b: &Family<()>) -> f64 {
        match self {
            Analytic::Constant => 1.0,
            Analytic::Linear => a.mass + b.mass,
            Analytic::Product => a.mass * b.mass,
        }
    }

    fn collide(&self, target: &Family<()>, projectile: &Family<()>) -> Collision {
        let _ = projectile;
        Collision::Stick { change: 1.0 - target.filling }
    }
}

impl Analytic {
    /// Exact number density N_k(t) of k-mers from monomers with N₀ = 1 at t = 0.
    pub fn exact(&self, k: u64, t: f64) -> f64 {
        self.density(k as f64, ln_factorial(k), t)
    }

    /// Exact mass per unit volume between masses `lo` and `hi` (k-mers with
    /// lo ≤ k < hi).
    /// Summed term by term below k = 10⁴; above, k N_k is smooth and the sum is
    /// integrated over ln k (Simpson, 400 intervals).
    pub fn exact_mass_between(&self, lo: f64, hi: f64, t: f64) -> f64 {
        const DIRECT: f64 = 1e4;
        let k0 = lo.ceil().max(1.0);
        let k1 = hi.ceil();
        let mut sum: f64 = (k0 as u64..k1.min(DIRECT) as u64).map(|k| k as f64 * self.exact(k, t)).sum();
        let (a, b) = (k0.max(DIRECT), k1);
        if b > a {
            let n = 400;
            let (la, lb) = ((a - 0.5).ln(), (b - 0.5).ln());
            let h = (lb - la) / n as f64;
            let f = |x: f64| {
                let k = x.exp();
                k * k * self.exact_continuous(k, t)
            };
            let inner: f64 = (1..n).map(|i| f(la + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 }).sum();
            sum += h / 3.0 * (f(la) + inner + f(lb));
        }
        sum
    }

    /// Exact mass per unit volume per unit ln m at mass k (real, k ≫ 1, where
    /// N_k is smooth in k): k²N_k.
    pub fn exact_mass_per_ln(&self, k: f64, t: f64) -> f64 {
        k * k * self.exact_continuous(k, t)
    }

    /// N_k for real k (Stirling's ln Γ(k + 1)).
    fn exact_continuous(&self, k: f64, t: f64) -> f64 {
        let ln_fact = k * k.ln() - k + 0.5 * (2.0 * std::f64::consts::PI * k).ln() + 1.0 / (12.0 * k);
        self.density(k, ln_fact, t)
    }

    /// N_k(t) given ln k!.
    fn density(&self, k: f64, ln_fact: f64, t: f64) -> f64 {
        match self {
            Analytic::Constant => {
                let x = t / 2.0;
                ((k - 1.0) * x.ln() - (k + 1.0) * (1.0 + x).ln()).exp()
            }
            Analytic::Linear => {
                let g = (-t).exp();
                let y = k * (1.0 - g);
                (g.ln() + (k - 1.0) * y.ln() - y - ln_fact).exp()
            }
            Analytic::Product => ((k - 1.0) * (k * t).ln() - k * t - k.ln() - ln_fact).exp(),
        }
    }
}

/// ln k! (exact sum below 30, Stirling series above).
fn ln_factorial(k: u64) -> f64 {
    if k < 30 {
        (1..=k).map(|i| (i as f64).ln()).sum()
    } else {
        let x = k as f64;
        x * x.ln() - x + 0.5 * (2.0 * std::f64::consts::PI * x).ln() + 1.0 / (12.0 * x) - 1.0 / (360.0 * x.powi(3))
    }
}

/// Settings of the distribution method.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Desired groups per mass decade, w* (60 for perfect sticking, 40 with erosion in the thesis).
    pub groups_per_decade: f64,
    /// Largest fractional mass change of a particle in one group event, f_m (0.1).
    pub f_m: f64,
    /// Largest fractional filling-factor change in one group event, f_φ (0.1).
    pub f_phi: f64,
    /// Re-zoom at least every this many events (100); also when m_a or m_p
    /// changed by 5 % or m_max by 50 % since the last re-zoom.
    pub rezoom_every: usize,
    /// Random seed.
    pub seed: u64,
    /// Largest share of the total mass one group may hold, ε_M
    /// (dimensionless, 0 < ε_M ≤ 1; 1 = no cap, as in the thesis). Below 1
    /// the zoom factor of a family of mass m is also at most
    /// ⌊log₂(ε_M M/m)⌋: the most massive particles are followed in smaller
    /// groups than (4.26) alone gives.
    pub group_mass_cap: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Settings { groups_per_decade: 60.0, f_m: 0.1, f_phi: 0.1, rezoom_every: 100, seed: 1, group_mass_cap: 1.0 }
    }
}

/// Why a run cannot start.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EngineError {
    /// A setting or initial condition is out of range.
    #[error("{0}")]
    Invalid(&'static str),
}

/// A symmetric matrix over the families, stored in full and row by row with
/// a capacity that doubles as families are added: a family's row is contiguous
/// for the sweeps over its partners, and the column is kept equal to it.
#[derive(Debug, Clone)]
struct Symmetric<T> {
    /// Families there is room for.
    capacity: usize,
    /// Entries from one row to the next: the capacity and one cache line
    /// more, so that the entries of a column fall into different cache sets
    /// (a power-of-two stride puts a whole column into one).
    stride: usize,
    data: Vec<T>,
}

impl<T: Copy + Default> Symmetric<T> {
    fn new() -> Self {
        Symmetric { capacity: 0, stride: 0, data: Vec::new() }
    }

    /// Room for `n` families, keeping the first `used` rows and columns.
    fn reserve(&mut self, n: usize, used: usize) {
        if n <= self.capacity {
            return;
        }
        let capacity = n.next_power_of_two().max(16);
        let stride = capacity + (64 / std::mem::size_of::<T>().max(1)).max(1);
        let mut data = vec![T::default(); stride * capacity];
        let used = used.min(self.capacity);
        for i in 0..used {
            data[i * stride..i * stride + used].copy_from_slice(&self.data[i * self.stride..i * self.stride + used]);
        }
        *self = Symmetric { capacity, stride, data };
    }

    fn get(&self, i: usize, j: usize) -> T {
        self.data[i * self.stride + j]
    }

    /// Entries (i, j) and (j, i).
    fn set(&mut self, i: usize, j: usize, value: T) {
        self.data[i * self.stride + j] = value;
        self.data[j * self.stride + i] = value;
    }

    /// Entry (i, j) alone (its mirror (j, i) is left as it is).
    fn at(&mut self, i: usize, j: usize) -> &mut T {
        &mut self.data[i * self.stride + j]
    }

    /// The first `n` entries of row i.
    fn row(&self, i: usize, n: usize) -> &[T] {
        &self.data[i * self.stride..i * self.stride + n]
    }

    /// The first `n` entries of row i, to write (the column is then
    /// made equal to it with [`Symmetric::mirror_row`]).
    fn row_mut(&mut self, i: usize, n: usize) -> &mut [T] {
        &mut self.data[i * self.stride..i * self.stride + n]
    }

    /// The data of index `from` move to index `to` (both < n); `from`'s are
    /// left as they were.
    fn relocate(&mut self, from: usize, to: usize, n: usize) {
        for j in 0..n {
            self.prefetch_column(to, j, n);
            let value = if j == to { self.get(from, from) } else { self.get(from, j) };
            self.set(to, j, value);
        }
    }

    /// Row `to` takes the first `n` entries of index `from`: entry j from row
    /// `from` where `in_row(j)`, from column `from` otherwise (where the newer
    /// of two families' data lie), and (to, to) from (from, from). Column
    /// `to` is left as it is.
    fn take_over(&mut self, from: usize, to: usize, n: usize, in_row: impl Fn(usize) -> bool) {
        for j in 0..n {
            let value = if j == to {
                self.get(from, from)
            } else if in_row(j) {
                self.get(from, j)
            } else {
                self.get(j, from)
            };
            *self.at(to, j) = value;
        }
    }

    /// Copies the first `n` entries of row i into column i.
    fn mirror_row(&mut self, i: usize, n: usize) {
        for j in 0..n {
            self.prefetch_column(i, j, n);
            self.data[j * self.stride + i] = self.data[i * self.stride + j];
        }
    }

    /// Asks for the cache line of entry (j + 16, i) of column i, to be
    /// written sixteen entries on: a column's entries lie a row apart, each
    /// in a cache line of its own, and written one after the other each
    /// waits for its line, where asked for ahead they arrive side by side.
    #[inline(always)]
    fn prefetch_column(&self, i: usize, j: usize, n: usize) {
        #[cfg(target_arch = "x86_64")]
        if j + 16 < n {
            let ahead = self.data[(j + 16) * self.stride + i..].as_ptr();
            // SAFETY: a prefetch only hints to the cache: it reads and writes nothing.
            unsafe { std::arch::x86_64::_mm_prefetch::<{ std::arch::x86_64::_MM_HINT_T0 }>(ahead.cast()) };
        }
        #[cfg(not(target_arch = "x86_64"))]
        let _ = (i, j, n);
    }
}

/// Cached data of a pair of families (the same for (i, j) and (j, i)).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pair {
    /// K/V, s⁻¹ (pair collision rate; 0 for pairs that bounce).
    pub c: f64,
    /// The smaller of ⌊log₂(f_m m_t/|δm|)⌋ and ⌊log₂(f_φ φ_t/|δφ|)⌋ of the
    /// target (+∞ without change), so that N_ε = ⌈max(z_hi − z_lo − these)⌉
    /// (4.22)–(4.24), and ⌈z − h⌉ = z − ⌊h⌋ for integer z. Integers and ±∞,
    /// exact in f32.
    pub headroom: f32,
}

/// A row of pair data, one array per field: the engine keeps K/V and the
/// headroom in matrices of their own, so that a row's loop writes each in
/// vectors straight into its row.
#[derive(Debug)]
pub struct PairRow<'a> {
    /// K/V of each pair.
    pub c: &'a mut [f64],
    /// The headroom of each pair.
    pub headroom: &'a mut [f32],
}

impl PairRow<'_> {
    /// Writes pair j.
    #[inline]
    pub fn set(&mut self, j: usize, pair: Pair) {
        self.c[j] = pair.c;
        self.headroom[j] = pair.headroom;
    }
}

/// A row of pair data of its own (K/V and headroom, one vector each), where
/// a row is computed outside an engine.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct OwnedRow {
    /// K/V of each pair.
    pub c: Vec<f64>,
    /// The headroom of each pair.
    pub headroom: Vec<f32>,
}

impl OwnedRow {
    /// `n` pairs with K/V 0 and headroom 0.
    pub fn new(n: usize) -> Self {
        OwnedRow { c: vec![0.0; n], headroom: vec![0.0; n] }
    }

    /// The row to write.
    pub fn row(&mut self) -> PairRow<'_> {
        PairRow { c: &mut self.c, headroom: &mut self.headroom }
    }

    /// Pair j.
    pub fn get(&self, j: usize) -> Pair {
        Pair { c: self.c[j], headroom: self.headroom[j] }
    }

    /// The number of pairs.
    pub fn len(&self) -> usize {
        self.c.len()
    }

    /// Whether the row has no pairs.
    pub fn is_empty(&self) -> bool {
        self.c.is_empty()
    }
}

/// The data of every pair of a run's families: K/V and the headroom in a
/// [`Symmetric`] matrix each.
#[derive(Debug, Clone)]
struct PairMatrix {
    c: Symmetric<f64>,
    headroom: Symmetric<f32>,
}

impl PairMatrix {
    fn new() -> Self {
        PairMatrix { c: Symmetric::new(), headroom: Symmetric::new() }
    }

    /// Room for `n` families, keeping the first `used` rows and columns.
    fn reserve(&mut self, n: usize, used: usize) {
        self.c.reserve(n, used);
        self.headroom.reserve(n, used);
    }

    fn get(&self, i: usize, j: usize) -> Pair {
        Pair { c: self.c.get(i, j), headroom: self.headroom.get(i, j) }
    }

    /// Row `to` takes family `from`'s pair data with the first `n` families;
    /// see [`Symmetric::take_over`].
    fn take_over(&mut self, from: usize, to: usize, n: usize, in_row: impl Fn(usize) -> bool) {
        self.c.take_over(from, to, n, &in_row);
        self.headroom.take_over(from, to, n, &in_row);
    }

    /// The first `n` entries of row i.
    fn row(&self, i: usize, n: usize) -> (&[f64], &[f32]) {
        (self.c.row(i, n), self.headroom.row(i, n))
    }

    /// The first `n` entries of row i, to write.
    fn row_mut(&mut self, i: usize, n: usize) -> PairRow<'_> {
        PairRow { c: self.c.row_mut(i, n), headroom: self.headroom.row_mut(i, n) }
    }
}

/// What turns a model's rate coefficient and effect into a pair's cached
/// data ([`Pair`]): the simulated volume and the limits f_m, f_φ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairRule {
    /// Simulated volume (or column area) V.
    pub volume: f64,
    /// Largest fractional mass change of a particle in one group event, f_m.
    pub f_m: f64,
    /// Largest fractional filling-factor change in one group event, f_φ.
    pub f_phi: f64,
}

impl PairRule {
    /// The cached data of pair (a, b), (K/V, headroom), from the model's
    /// rate coefficient and effect.
    pub fn data<P>(&self, a: &Family<P>, b: &Family<P>, rate: f64, effect: Effect) -> Pair {
        let (t, p) = if a.mass >= b.mass { (a, b) } else { (b, a) };
        let c = rate * (1.0 / self.volume);
        let (dm, dphi, c) = match effect {
            Effect::Stick { change } => (p.mass, change.abs(), c),
            Effect::Erode { loss } => (loss, 0.0, c),
            Effect::Shatter => (t.mass, t.filling, c),
            // Nothing happens: such events are left out.
            Effect::Bounce => (0.0, 0.0, 0.0),
        };
        let headroom = room(self.f_m, t.mass, dm).min(room(self.f_phi, t.filling, dphi));
        // An integer (|h| < 2¹¹) or ±∞: exact in f32.
        Pair { c, headroom: headroom as f32 }
    }
}

/// ⌊log₂(f x/dx)⌋, or +∞ where dx ≤ 0 (no change). Where f x and dx are
/// positive normal numbers it is read off their binary exponents and
/// significands (the floor of the exact ratio, without a division);
/// elsewhere it is taken from the rounded ratio.
fn room(f: f64, x: f64, dx: f64) -> f64 {
    if dx <= 0.0 {
        return f64::INFINITY;
    }
    let fx = f * x;
    let normal = |y: f64| y > 0.0 && y.is_normal();
    if normal(fx) && normal(dx) {
        floor_log2(fx) - floor_log2(dx) - if significand_of(fx) < significand_of(dx) { 1.0 } else { 0.0 }
    } else {
        floor_log2(fx / dx)
    }
}

/// The significand of a positive normal number, in [1, 2).
fn significand_of(y: f64) -> f64 {
    f64::from_bits((y.to_bits() & SIGNIFICAND) | 1f64.to_bits())
}

/// The significand's bits of an `f64`.
pub(crate) const SIGNIFICAND: u64 = (1 << 52) - 1;

/// Counts of what the events did.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct Tally {
    /// Group events that stuck.
    pub stick: u64,
    /// Group events that eroded.
    pub erode: u64,
    /// Group events that shattered.
    pub shatter: u64,
    /// Group events that bounced.
    pub bounce: u64,
    /// Families merged (4.27).
    pub merges: u64,
    /// Re-zooms.
    pub rezooms: u64,
}

/// The state of a Monte Carlo coagulation run.
#[derive(Debug, Clone)]
pub struct Engine<M: Model> {
    model: M,
    settings: Settings,
    families: Vec<Family<M::Props>>,
    /// Simulated volume (or column area): the pair rate is K/V.
    volume: f64,
    /// Simulated time.
    time: f64,
    /// Group events so far.
    events: u64,
    initial_mass: f64,
    /// The data of every pair: pair (i, j) is in row i if family i's data
    /// were computed after family j's (`computed`), in row j otherwise, so
    /// that computing a family's data writes one row.
    pairs: PairMatrix,
    /// When each family's pair data were computed (a count of rows computed).
    computed: Vec<u64>,
    /// Rows computed so far.
    rows: u64,
    /// Group event rate (4.25) of each pair per group of each family,
    /// 2^{z_lo + N_ε} K/V (0 on the diagonal): the rate of the pair (i ≠ j)
    /// is w_i w_j times this. Kept symmetric (rows are summed for any family).
    units: Symmetric<f64>,
    /// Twice each family's in-group event rate.
    in_group: Vec<f64>,
    /// Σ_{j ≠ i} w_j × unit(i, j) with the group counts in `counted`: family
    /// i's events with others happen at w_i times this.
    partner_sum: Vec<f64>,
    /// The group count of each family that `partner_sum` holds (equal to the
    /// family's own whenever an event is drawn).
    counted: Vec<f64>,
    /// Event weight of each family, w_i × partner_sum_i + in_group_i (twice
    /// the total rate summed), made afresh for each draw.
    weight: Vec<f64>,
    /// (m_a, m_p, m_max) at the last re-zoom.
    zoomed_at: (f64, f64, f64),
    since_zoom: usize,
    /// Largest total weight since the partner sums were last summed afresh.
    weight_scale: f64,
    /// Families whose zoom factor changed in the re-zoom under way.
    dirty: Vec<bool>,
    /// Families whose particles changed in the merges under way (their pair
    /// data are recomputed when the merges are done).
    stale: Vec<bool>,
    /// Families whose rates are in the partner sums: false for a family
    /// made by the event under way until its pair data and rates are first
    /// computed (its groups are not counted until then).
    rated: Vec<bool>,
    /// Families whose group count may have fallen below one since the
    /// merges were last done (the only ones `merge_small` need look at),
    /// unless `watch_all`.
    watch: Vec<usize>,
    /// Every family may hold fewer than one group (after a re-zoom).
    watch_all: bool,
    /// The particles each family's properties and pair data were computed
    /// for: merges that keep them move the family's mass and φ by at most
    /// `MERGE_REFRESH` from these in all, not per merge.
    cached: Vec<Body>,
    /// The indices of the families in order of mass.
    by_mass: Vec<usize>,
    /// The particles in each mass decade (keyed by ⌊log₁₀ m⌋) at the last
    /// re-zoom, from which z*(m) (4.26) is taken.
    decades: std::collections::BTreeMap<i64, f64>,
    /// The model's lanes of the families.
    lanes: M::Lanes,
    /// Each family's mass and zoom factor, one after another (what the
    /// unit rates of a row read).
    keys: Vec<Key>,
    /// A row of pair data gathered from rows and columns, kept to reuse its allocation.
    row_pairs: OwnedRow,
    tally: Tally,
    rng: rand::rngs::StdRng,
}

impl<M: Model> Engine<M> {
    /// Starts from `particles` identical particles `first` in volume `volume`.
    pub fn new(model: M, first: Body, particles: f64, volume: f64, settings: Settings) -> Result<Self, EngineError> {
        if !(first.mass > 0.0 && first.mass.is_finite()) {
            return Err(EngineError::Invalid("the initial particle mass must be finite and > 0"));
        }
        if !(first.filling > 0.0 && first.filling <= 1.0) {
            return Err(EngineError::Invalid("the initial filling factor must be in (0, 1]"));
        }
        if !(particles >= 2.0 && particles.is_finite()) {
            return Err(EngineError::Invalid("need at least 2 particles"));
        }
        if !(volume > 0.0 && volume.is_finite()) {
            return Err(EngineError::Invalid("the simulated volume must be finite and > 0"));
        }
        let s = settings;
        if !(s.groups_per_decade >= 2.0 && s.groups_per_decade <= 1e4) {
            return Err(EngineError::Invalid("groups per decade w* must be in [2, 10⁴]"));
        }
        if !(s.f_m > 0.0 && s.f_m <= 1.0 && s.f_phi > 0.0 && s.f_phi <= 1.0 && s.rezoom_every >= 1) {
            return Err(EngineError::Invalid("need 0 < f_m, f_φ ≤ 1 and a re-zoom interval ≥ 1"));
        }
        if !(s.group_mass_cap > 0.0 && s.group_mass_cap <= 1.0) {
            return Err(EngineError::Invalid("the group mass cap ε_M must be in (0, 1]"));
        }
        let zoom = zoom_for(particles, s.groups_per_decade).min(capped_zoom(
            first.mass,
            first.mass * particles,
            s.group_mass_cap,
        ));
        let props = model.props(first);
        let family = Family { mass: first.mass, filling: first.filling, groups: particles / exp2i(zoom), zoom, props };
        let mut e = Engine {
            model,
            settings,
            families: vec![family],
            volume,
            time: 0.0,
            events: 0,
            initial_mass: first.mass * particles,
            pairs: PairMatrix::new(),
            computed: vec![0],
            rows: 0,
            units: Symmetric::new(),
            in_group: vec![0.0],
            partner_sum: vec![0.0],
            counted: vec![0.0],
            weight: Vec::new(),
            zoomed_at: (first.mass, first.mass, first.mass),
            since_zoom: 0,
            dirty: vec![false],
            stale: vec![false],
            rated: vec![true],
            watch: Vec::new(),
            watch_all: false,
            cached: vec![first],
            by_mass: vec![0],
            decades: std::collections::BTreeMap::new(),
            lanes: M::Lanes::default(),
            keys: vec![Key { mass: family.mass, zoom: family.zoom }],
            row_pairs: OwnedRow::default(),
            weight_scale: 0.0,
            tally: Tally::default(),
            rng: rand::rngs::StdRng::seed_from_u64(settings.seed),
        };
        e.model.set_lane(&mut e.lanes, 0, &e.families[0]);
        e.reserve(1);
        e.refresh_pairs(0);
        Ok(e)
    }

    /// The collision model.
    pub fn model(&self) -> &M {
        &self.model
    }

    /// The families.
    pub fn families(&self) -> &[Family<M::Props>] {
        &self.families
    }

    /// Simulated volume (or column area).
    pub fn volume(&self) -> f64 {
        self.volume
    }

    /// Simulated time.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Group events so far.
    pub fn events(&self) -> u64 {
        self.events
    }

    /// What the events did.
    pub fn tally(&self) -> Tally {
        self.tally
    }

    /// Total mass now, Σ m g.
    pub fn mass(&self) -> f64 {
        self.families.iter().map(|f| f.mass * f.particles()).sum()
    }

    /// Total mass at the start.
    pub fn initial_mass(&self) -> f64 {
        self.initial_mass
    }

    /// Total group event rate.
    pub fn total_rate(&self) -> f64 {
        0.5 * (0..self.families.len()).map(|i| self.event_weight(i)).sum::<f64>()
    }

    /// Average mass m_a, peak mass m_p (4.28)–(4.29) and largest mass.
    pub fn moments(&self) -> (f64, f64, f64) {
        moments_of(self.families.iter().map(|f| (f.particles(), f.mass)))
    }

    /// [`Engine::moments`] from the group counts in `counted` and the
    /// masses and zoom factors in `keys` (compact arrays beside the
    /// families), where they equal the families' own.
    fn counted_moments(&self) -> (f64, f64, f64) {
        debug_assert!(self.families.iter().zip(&self.counted).all(|(f, g)| f.groups == *g));
        moments_in_chains(&self.keys, &self.counted)
    }

    /// Average and peak filling factors φ_a = ⟨φ⟩, φ_p = ⟨mφ⟩/⟨m⟩ (4.28)–(4.29).
    pub fn filling_moments(&self) -> (f64, f64) {
        let (mut n, mut m1, mut phi, mut mphi) = (0.0, 0.0, 0.0, 0.0);
        for f in &self.families {
            let g = f.particles();
            n += g;
            m1 += g * f.mass;
            phi += g * f.filling;
            mphi += g * f.mass * f.filling;
        }
        (phi / n, mphi / m1)
    }

    /// Index of the family with the largest particles.
    pub fn largest(&self) -> usize {
        (0..self.families.len()).max_by(|&a, &b| self.families[a].mass.total_cmp(&self.families[b].mass)).unwrap_or(0)
    }

    /// The projectile distribution of family `t` (Okuzumi et al. 2009, thesis
    /// Fig. 4.10): for every family j with m_j ≤ m_t, the rate of change of
    /// m_t from collisions with j-particles, (m_j, Σ K n_j δm_t) — positive
    /// for sticking, negative for erosion.
    pub fn projectile_distribution(&self, t: usize) -> Vec<(f64, f64)> {
        let target = &self.families[t];
        let mut out = Vec::new();
        for (j, f) in self.families.iter().enumerate() {
            if f.mass > target.mass {
                continue;
            }
            let partners = if j == t { (f.particles() - 1.0).max(0.0) } else { f.particles() };
            let c = self.c(t, j);
            let dm = match self.model.collide(target, f) {
                Collision::Stick { .. } => f.mass,
                Collision::Erode { loss, .. } => -loss,
                Collision::Shatter { .. } => -target.mass,
                Collision::Bounce => 0.0,
            };
            out.push((f.mass, c * partners * dm));
        }
        crate::sorting::sort_by_key(&mut out, |a| a.0);
        out
    }

    /// N_ε and the order (lo, hi) of a pair: lo has the lower zoom factor
    /// (ties: the more massive). 2^{z_lo} lo-particles each meet
    /// 2^{z_hi − z_lo − N_ε} hi-particles in one event (4.21)–(4.24).
    fn order(&self, i: usize, j: usize) -> (usize, usize, i32) {
        let (lo_first, n_eps) = order_of(&self.families[i], i, &self.families[j], j, self.data(i, j).headroom);
        if lo_first { (i, j, n_eps) } else { (j, i, n_eps) }
    }

    /// In-group event rate (4.20): two groups meet particle by particle,
    /// 2^z pair collisions per event, so the rate is the family's pair rate
    /// g(g − 1)/2 · K/V divided by 2^z.
    fn in_group_rate(&self, i: usize) -> f64 {
        let c = self.c(i, i);
        let f = &self.families[i];
        if c <= 0.0 {
            0.0
        } else if f.groups >= 2.0 {
            0.5 * f.groups * (f.particles() - 1.0) * c
        } else if f.zoom >= 1 {
            // One group pairs up internally: 2^{z−1} pair collisions per event.
            f.groups * (f.particles() - 1.0) * c
        } else {
            0.0
        }
    }

    /// The cached data of pair (i, j), from the row of the family whose data
    /// were computed last.
    #[inline(always)]
    fn data(&self, i: usize, j: usize) -> Pair {
        if self.computed[i] >= self.computed[j] { self.pairs.get(i, j) } else { self.pairs.get(j, i) }
    }

    /// K/V of pair (i, j).
    fn c(&self, i: usize, j: usize) -> f64 {
        self.data(i, j).c
    }

    /// Family i's share of twice the total event rate.
    fn event_weight(&self, i: usize) -> f64 {
        self.families[i].groups * self.partner_sum[i] + self.in_group[i]
    }

    /// Room in the pair matrices for `n` families.
    fn reserve(&mut self, n: usize) {
        let used = self.families.len();
        self.pairs.reserve(n, used);
        self.units.reserve(n, used);
    }

    /// Recomputes the cached pair data of family k (its body changed), then its rates.
    fn refresh_pairs(&mut self, k: usize) {
        let n = self.families.len();
        let rule = PairRule { volume: self.volume, f_m: self.settings.f_m, f_phi: self.settings.f_phi };
        // Row k, now the newest, holds the pair data.
        let row = self.pairs.row_mut(k, n);
        self.model.pair_data_row(&self.lanes, &self.families[k], &self.families, &self.by_mass, &rule, row);
        self.rows += 1;
        self.computed[k] = self.rows;
        self.refresh_rates(k);
    }

    /// Recomputes the group rates of family k (its zoom, groups or pair data changed).
    fn refresh_rates(&mut self, k: usize) {
        let n = self.families.len();
        let (now, before) = (self.families[k].groups, self.counted[k]);
        let at = self.computed[k];
        // The pair data of row k, from wherever they are (after its pair
        // data were computed, from row k itself).
        // Row k computed last (the usual case, right after its pair data)
        // needs no look at the others.
        let pairs = if at == self.rows || self.computed.iter().all(|&c| c <= at) {
            self.pairs.row(k, n)
        } else {
            let ((own_c, own_h), pairs) = (self.pairs.row(k, n), &self.pairs);
            let gathered = &mut self.row_pairs;
            gathered.c.clear();
            gathered.headroom.clear();
            for (j, ((&c, &h), &when)) in own_c.iter().zip(own_h).zip(&self.computed).enumerate() {
                let p = if at >= when { Pair { c, headroom: h } } else { pairs.get(j, k) };
                gathered.c.push(p.c);
                gathered.headroom.push(p.headroom);
            }
            (&gathered.c[..], &gathered.headroom[..])
        };
        // Each pair's unit rate and the partner's sum, pair by pair in the
        // order of the families, in vectors where the processor has them.
        let fk = &self.families[k];
        let lead = (fk.zoom, fk.mass, k);
        unit_row(lead, (now, before), &self.keys, pairs, self.units.row_mut(k, n), &mut self.partner_sum[..n]);
        // Family k's own sum (unit(k, k) = 0).
        let sum = dot_in_chains(self.units.row(k, n), &self.counted[..n]);
        self.units.mirror_row(k, n);
        self.partner_sum[k] = sum;
        self.counted[k] = now;
        self.in_group[k] = 2.0 * self.in_group_rate(k);
        self.rated[k] = true;
    }

    /// Updates the rates after family k's group count changed (nothing else
    /// about it): a pair's group rate (4.25) is proportional to the group
    /// counts of both families, so every partner's sum moves by the change
    /// times the pair's unit rate; the in-group rate is recomputed. Nothing
    /// for a family not yet rated.
    fn scale_rates(&mut self, k: usize) {
        if !self.rated[k] {
            // Its groups are counted when its rates are first computed.
            return;
        }
        let n = self.families.len();
        let change = self.families[k].groups - self.counted[k];
        if change != 0.0 {
            for (sum, unit) in self.partner_sum.iter_mut().zip(self.units.row(k, n)) {
                // unit(k, k) = 0: family k's own sum is untouched.
                *sum += change * unit;
            }
        }
        self.counted[k] = self.families[k].groups;
        self.in_group[k] = 2.0 * self.in_group_rate(k);
    }

    /// Sums every partner sum afresh from the unit rates (no accumulated rounding).
    fn sum_afresh(&mut self) {
        let n = self.families.len();
        for i in 0..n {
            self.counted[i] = self.families[i].groups;
            self.in_group[i] = 2.0 * self.in_group_rate(i);
        }
        for i in 0..n {
            self.partner_sum[i] = self.units.row(i, n).iter().zip(&self.counted).map(|(u, g)| u * g).sum();
        }
        self.weight_scale = (0..n).map(|i| self.event_weight(i)).sum();
    }

    /// Adds a family of `particles` particles `body` at zoom `zoom`, its pair
    /// data to be computed when the event's merges are done (`tidy`).
    fn add_family(&mut self, body: Body, particles: f64, zoom: i32) {
        let props = self.model.props(body);
        let family = Family { mass: body.mass, filling: body.filling, groups: particles / exp2i(zoom), zoom, props };
        let k = self.families.len();
        self.reserve(k + 1);
        // Its pair data are empty, and newer than any until they are
        // computed (when the event's merges are done; nothing reads them
        // before).
        let row = self.pairs.row_mut(k, k + 1);
        row.c.fill(0.0);
        row.headroom.fill(0.0);
        self.units.row_mut(k, k + 1).fill(0.0);
        self.rows += 1;
        self.model.set_lane(&mut self.lanes, k, &family);
        self.keys.push(Key { mass: family.mass, zoom: family.zoom });
        self.families.push(family);
        self.in_group.push(0.0);
        self.partner_sum.push(0.0);
        self.counted.push(0.0);
        self.dirty.push(false);
        self.stale.push(true);
        self.rated.push(false);
        self.watch.push(k);
        self.cached.push(body);
        self.computed.push(self.rows);
        self.enlist(k);
    }

    /// Puts family k into `by_mass` at its mass.
    fn enlist(&mut self, k: usize) {
        let m = self.families[k].mass;
        let at = self.by_mass.partition_point(|&i| self.families[i].mass < m);
        self.by_mass.insert(at, k);
    }

    /// Takes family k out of `by_mass` (before its mass changes).
    fn unlist(&mut self, k: usize) {
        let m = self.families[k].mass;
        let from = self.by_mass.partition_point(|&i| self.families[i].mass < m);
        if let Some(at) = self.by_mass[from..].iter().position(|&i| i == k) {
            self.by_mass.remove(from + at);
        }
    }

    /// Removes family k; the last family takes its index.
    fn remove_family(&mut self, k: usize) {
        let n = self.families.len();
        let counted = self.counted[k];
        if counted != 0.0 {
            for (sum, unit) in self.partner_sum.iter_mut().zip(self.units.row(k, n)) {
                *sum -= counted * unit;
            }
        }
        self.unlist(k);
        let last = n - 1;
        if k != last {
            self.unlist(last);
            // A family made by this event and not yet rated (usually the one
            // that moves: products are added last) keeps nothing worth
            // moving: its pair data and unit rates are computed afresh, over
            // its whole row and column, when the merges are done, and until
            // then no partner sum holds its rates (`scale_rates` leaves them
            // out while it is unrated), so whatever its new row and column
            // hold is never summed into a rate.
            if self.rated[last] {
                // The pair data go to row k, from wherever they are; row k
                // then counts as the newest, so that they are read from there.
                let (computed, newest) = (&self.computed, self.computed[last]);
                self.pairs.take_over(last, k, last, |j| newest >= computed[j]);
                self.units.relocate(last, k, last);
            }
        }
        self.computed.swap_remove(k);
        if k != last {
            self.rows += 1;
            self.computed[k] = self.rows;
        }
        self.in_group.swap_remove(k);
        self.partner_sum.swap_remove(k);
        self.counted.swap_remove(k);
        self.dirty.swap_remove(k);
        self.stale.swap_remove(k);
        self.rated.swap_remove(k);
        self.watch.retain(|&w| w != k);
        for w in &mut self.watch {
            if *w == last {
                *w = k;
            }
        }
        self.cached.swap_remove(k);
        self.families.swap_remove(k);
        self.keys.swap_remove(k);
        self.model.remove_lane(&mut self.lanes, k);
        if k != last {
            self.enlist(k);
        }
    }

    /// Performs one group event; returns false if no event is possible.
    pub fn step(&mut self) -> bool {
        let mut total2 = self.weigh();
        // Partner sums are updated incrementally; when the total falls far
        // below the largest it had, their rounding could matter: sum afresh.
        if total2.is_nan() || total2 <= 1e-9 * self.weight_scale {
            self.sum_afresh();
            total2 = self.weigh();
            self.weight_scale = total2;
        }
        self.weight_scale = self.weight_scale.max(total2);
        if total2.is_nan() || total2 <= 0.0 {
            // Families may hold too few groups for their zoom factors.
            self.rezoom();
            total2 = self.weigh();
        }
        if !(total2 > 0.0 && total2.is_finite()) {
            return false;
        }
        let u: f64 = self.rng.random::<f64>();
        self.time += -(1.0 - u).ln() / (0.5 * total2);
        let i = pick(&self.weight, self.rng.random::<f64>() * total2);
        let target = self.rng.random::<f64>() * self.weight[i];
        let j = self.partner(i, target);
        self.event(i, j);
        self.events += 1;
        self.since_zoom += 1;
        let (m_a, m_p, m_max) = self.counted_moments();
        let moved = |now: f64, then: f64, by: f64| (now / then - 1.0).abs() > by;
        if self.since_zoom >= self.settings.rezoom_every
            || moved(m_a, self.zoomed_at.0, 0.05)
            || moved(m_p, self.zoomed_at.1, 0.05)
            || moved(m_max, self.zoomed_at.2, 0.5)
        {
            self.rezoom();
        }
        true
    }

    /// Makes every family's event weight; returns their sum (twice the total rate).
    fn weigh(&mut self) -> f64 {
        debug_assert!(self.families.iter().zip(&self.counted).all(|(f, g)| f.groups == *g));
        debug_assert!(!self.stale.contains(&true));
        // `event_weight` from the group counts in `counted` (equal to the
        // families' own here), a compact array beside the families.
        self.weight.resize(self.counted.len(), 0.0);
        for (weight, ((groups, sum), in_group)) in
            self.weight.iter_mut().zip(self.counted.iter().zip(&self.partner_sum).zip(&self.in_group))
        {
            *weight = groups * sum + in_group;
        }
        sum_in_chains(&self.weight)
    }

    /// The partner of family i in an event: itself with weight in_group_i,
    /// family j with weight w_i w_j unit(i, j); `target` is uniform in
    /// [0, weight_i).
    fn partner(&self, i: usize, target: f64) -> usize {
        let in_group = self.in_group[i];
        if target < in_group {
            return i;
        }
        let n = self.families.len();
        let scaled = (target - in_group) / self.families[i].groups;
        let none = if in_group > 0.0 { i } else { 0 };
        cumulative_pick(&Products(self.units.row(i, n), &self.counted[..n]), scaled, none)
    }

    /// Runs until time `t_end` or until `max_events` more events; returns
    /// false if no event was possible.
    pub fn run_until(&mut self, t_end: f64, max_events: u64) -> bool {
        let stop = self.events + max_events;
        while self.time < t_end && self.events < stop {
            if !self.step() {
                return false;
            }
        }
        true
    }

    fn event(&mut self, i: usize, j: usize) {
        let mut made: Vec<Product> = Vec::with_capacity(2);
        if i == j {
            let f = self.families[i];
            if f.groups >= 2.0 {
                self.families[i].groups -= 2.0;
                self.outcome(&f, &f, 1.0, exp2i(f.zoom), f.zoom, &mut made);
            } else {
                self.families[i].groups -= 1.0;
                self.outcome(&f, &f, 1.0, exp2i(f.zoom - 1), f.zoom - 1, &mut made);
            }
        } else {
            let (lo, hi, n_eps) = self.order(i, j);
            let (l, h) = (self.families[lo], self.families[hi]);
            let per = exp2i(h.zoom - l.zoom - n_eps);
            self.families[lo].groups -= 1.0;
            self.families[hi].groups -= exp2i(-n_eps);
            self.outcome(&l, &h, per, exp2i(l.zoom), l.zoom, &mut made);
        }
        self.watch.extend([i, j]);
        self.scale_rates(i);
        if j != i {
            self.scale_rates(j);
        }
        for (body, count, zoom, kind) in made {
            if count > 0.0 && body.mass > 0.0 {
                self.add_product(body, count, zoom, kind);
            }
        }
        self.tidy();
    }

    /// Adds `count` particles `body` made by an event at zoom `zoom` (for
    /// fragments, their decade's zoom factor where that is larger: see
    /// [`Engine::decade_zoom`]). Too few to fill one group, they merge at
    /// once into the family `tidy` would merge them into (4.27), without
    /// computing pair data for a family that would not live to use it. The
    /// products of erosion and shattering (remnants, fragments, monomers)
    /// that differ from an existing family by no more than `MERGE_REFRESH` in
    /// mass and φ join it whatever their number: the family's properties and
    /// pair data do not change, and the next re-zoom would give them its zoom
    /// factor anyway. Products of sticking always start a family of their own
    /// when they fill a group.
    fn add_product(&mut self, body: Body, count: f64, zoom: i32, kind: Made) {
        let zoom = if kind == Made::Fragments { zoom.max(self.decade_zoom(body.mass, count)) } else { zoom };
        let groups = count / exp2i(zoom);
        if let Some(t) = self.most_similar_to(body, None) {
            let f = &self.families[t];
            let same = kind != Made::Stuck
                && (body.mass / f.mass - 1.0).abs() <= MERGE_REFRESH
                && (body.filling / f.filling - 1.0).abs() <= MERGE_REFRESH;
            if same || (1e-6..1.0 - 1e-9).contains(&groups) {
                if self.merge_particles_into(body, count, t) {
                    self.stale[t] = true;
                }
                self.scale_rates(t);
                return;
            }
        }
        self.add_family(body, count, zoom);
    }

    /// z*(m) (4.26) that the next re-zoom would give `count` new particles
    /// of mass m: from the particles in their mass decade at the last
    /// re-zoom and these. Fragments are made at the zoom factor that fills
    /// one group (or at this one, if larger): in a decade already well
    /// populated, most such families would hold less than one group at the
    /// next re-zoom and merge there, unused (in `mc-fig-4-10-4-11`'s column
    /// at v_eros = 40 m/s, 163 500 of 181 300 fragment families, each with
    /// its pair data computed, merged at the next re-zoom without an
    /// event). At this zoom factor they merge as they are made.
    fn decade_zoom(&self, mass: f64, count: f64) -> i32 {
        let n10 = self.decades.get(&decade_of(mass)).copied().unwrap_or(0.0) + count;
        z_star(n10, mass, self.initial_mass, &self.settings)
    }

    /// The products of `units` lo-particles each meeting `per` hi-particles;
    /// `per` > 1 only when lo is the target and extrapolates one collision (4.21).
    fn outcome(
        &mut self,
        lo: &Family<M::Props>,
        hi: &Family<M::Props>,
        per: f64,
        units: f64,
        zoom: i32,
        made: &mut Vec<Product>,
    ) {
        let lo_is_target = lo.mass >= hi.mass;
        let single = if lo_is_target { self.model.collide(lo, hi) } else { self.model.collide(hi, lo) };
        let target = if lo_is_target { lo } else { hi };
        let projectile = if lo_is_target { hi } else { lo };
        let grown = |dm: f64, dphi: f64| Body {
            mass: target.mass + per * dm,
            filling: (target.filling + per * dphi).clamp(1e-300, 1.0),
        };
        let model = &self.model;
        let compacted = |b: Body| Body { filling: model.compact(b), ..b };
        let fragment_zoom = |count: f64| count.log2().floor().max(0.0) as i32;
        match single {
            Collision::Stick { change } => {
                self.tally.stick += 1;
                made.push((compacted(grown(projectile.mass, change)), units, zoom, Made::Stuck));
            }
            Collision::Erode { loss, fragment, count } => {
                self.tally.erode += 1;
                let remnant = grown(-loss, 0.0);
                let lost = units * per * count;
                if remnant.mass > 0.0 {
                    made.push((remnant, units, zoom, Made::Broken));
                    made.push((compacted(fragment), lost, fragment_zoom(lost), Made::Fragments));
                } else {
                    // Cannot happen within the f_m limit; keep the mass anyway.
                    let all = units * (target.mass + per * projectile.mass);
                    let n = all / fragment.mass;
                    made.push((compacted(fragment), n, fragment_zoom(n), Made::Fragments));
                }
            }
            Collision::Shatter { fragment, count } => {
                self.tally.shatter += 1;
                let n = units * count;
                made.push((compacted(fragment), n, fragment_zoom(n), Made::Fragments));
                // A target that shatters in the first collision of its
                // sequence meets none of the other per − 1 hi-particles: they
                // stay as they were. (The sequence is set by the cached pair
                // data; a merge that moved a family by less than
                // MERGE_REFRESH keeps them, so a pair whose speed lies at
                // v_frag may be cached as sticking and shatter here.)
                if per > 1.0 {
                    made.push((hi.body(), units * (per - 1.0), zoom, Made::Stuck));
                }
            }
            Collision::Bounce => {
                // Left out by the rates; if reached, the particles are returned unchanged.
                self.tally.bounce += 1;
                made.push((lo.body(), units, zoom, Made::Stuck));
                made.push((hi.body(), units * per, zoom, Made::Stuck));
            }
        }
    }

    /// Merges families with fewer than one group into their most similar
    /// family (4.27); an empty family's rounding remainder goes the same way,
    /// so mass is conserved to rounding.
    fn tidy(&mut self) {
        self.merge_small(true);
    }

    /// Merges or magnifies every family with fewer than one group; with
    /// `refresh` the rates of magnified families are updated at once (a
    /// re-zoom marks them dirty instead).
    fn merge_small(&mut self, refresh: bool) {
        while let Some(k) = self.first_small() {
            if self.families[k].groups.abs() < 1e-6 {
                self.absorb_residue(k);
                self.remove_family(k);
                continue;
            }
            match self.merge_partner(k) {
                Some(t) => {
                    // A family that several merge into has its pair data
                    // recomputed once, after the last.
                    if self.merge_into(k, t) {
                        self.stale[t] = true;
                    }
                    self.scale_rates(t);
                    self.remove_family(k);
                }
                None => {
                    // Nothing similar: fewer particles per group instead.
                    if !self.magnify(k) {
                        break;
                    }
                    if refresh {
                        self.refresh_rates(k);
                    }
                }
            }
        }
        let mut k = 0;
        while let Some(at) = self.stale[k..].iter().position(|&stale| stale) {
            k += at;
            self.stale[k] = false;
            self.refresh_pairs(k);
            k += 1;
        }
    }

    /// The family with the lowest index that holds fewer than one group.
    /// Watched families that hold more stop being watched (a family's group
    /// count falls only where it is put on the watch).
    fn first_small(&mut self) -> Option<usize> {
        let families = &self.families;
        let small = |k: &usize| families[*k].groups < 1.0 - 1e-9;
        if self.watch_all {
            let first = (0..families.len()).find(small);
            self.watch_all = first.is_some();
            return first;
        }
        self.watch.retain(small);
        self.watch.iter().copied().min()
    }

    /// The rounding residue of an emptied family (|w| < 10⁻⁶ groups, either
    /// sign) goes to the family holding the most mass, as extra particles of
    /// that family's mass: mass stays conserved and the particle number
    /// changes by a negligible fraction.
    fn absorb_residue(&mut self, k: usize) {
        let f = self.families[k];
        let residue = f.mass * f.particles();
        let t = (0..self.families.len()).filter(|&i| i != k).max_by(|&a, &b| {
            let (x, y) = (&self.families[a], &self.families[b]);
            (x.mass * x.particles()).total_cmp(&(y.mass * y.particles()))
        });
        if let Some(t) = t {
            let g = &mut self.families[t];
            g.groups += residue / g.mass / exp2i(g.zoom);
            // The residue may be negative.
            self.watch.push(t);
            self.scale_rates(t);
        }
    }

    /// The family k merges into: the most similar healthy family if its
    /// particles are within a factor `MERGE_RATIO` in mass, or when family k
    /// holds less than one particle; otherwise none (merging would move mass
    /// across the distribution).
    fn merge_partner(&self, k: usize) -> Option<usize> {
        let t = self.most_similar(k)?;
        let (a, b) = (self.families[k].mass, self.families[t].mass);
        if a.max(b) / a.min(b) <= MERGE_RATIO || self.families[k].particles() < 1.0 { Some(t) } else { None }
    }

    /// Lowers the zoom factor of family k so that it holds at least one
    /// group; false if it holds less than one particle.
    fn magnify(&mut self, k: usize) -> bool {
        let f = self.families[k];
        if f.particles() < 1.0 {
            return false;
        }
        let z = f.particles().log2().floor().max(0.0) as i32;
        self.families[k].zoom = z;
        self.keys[k].zoom = z;
        self.dirty[k] = true;
        self.families[k].groups = f.particles() / exp2i(z);
        true
    }

    /// The healthy family most like family k: largest R^(m)(R^(φ))³ (Sect. 4.3.4).
    fn most_similar(&self, k: usize) -> Option<usize> {
        self.most_similar_to(self.families[k].body(), Some(k))
    }

    /// The healthy family (other than `except`) most like particles `body`.
    fn most_similar_to(&self, body: Body, except: Option<usize>) -> Option<usize> {
        let ratios = |g: &Family<M::Props>| {
            ((body.mass / g.mass).min(g.mass / body.mass), (body.filling / g.filling).min(g.filling / body.filling))
        };
        // R^(m)(R^(φ))³ as one quotient: (smaller mass)(smaller φ)³ over
        // (larger mass)(larger φ)³, with one division (both factors lie far
        // from underflow and overflow for masses and φ in the engine's range).
        let product = |g: &Family<M::Props>| {
            let (m_lo, m_hi) = if body.mass < g.mass { (body.mass, g.mass) } else { (g.mass, body.mass) };
            let (p_lo, p_hi) =
                if body.filling < g.filling { (body.filling, g.filling) } else { (g.filling, body.filling) };
            (m_lo * p_lo * p_lo * p_lo) / (m_hi * p_hi * p_hi * p_hi)
        };
        let healthy = |i: usize| Some(i) != except && self.families[i].groups > 0.0;
        let mass_ratio =
            |g: &Family<M::Props>| if body.mass < g.mass { body.mass / g.mass } else { g.mass / body.mass };
        // The product is at most the mass ratio, so the search walks out from
        // the body's mass in `by_mass` both ways and stops where the mass
        // ratio alone falls below what is needed. The product finds the few
        // candidates cheaply; among those within 10⁻⁹ of the best, the
        // logarithmic score decides, so that near-ties fall by the score of
        // Sect. 4.3.4 itself (exact ties: the higher index).
        let start = self.by_mass.partition_point(|&i| self.families[i].mass < body.mass);
        let (above, below) = (&self.by_mass[start..], &self.by_mass[..start]);
        let mut best = f64::NEG_INFINITY;
        for side in [&mut above.iter(), &mut below.iter().rev()] as [&mut dyn Iterator<Item = &usize>; 2] {
            for &i in side {
                let g = &self.families[i];
                if mass_ratio(g) < best * (1.0 - 1e-9) {
                    break;
                }
                if healthy(i) {
                    best = best.max(product(g));
                }
            }
        }
        let score = |g: &Family<M::Props>| {
            let (rm, rp) = ratios(g);
            rm.ln() + 3.0 * rp.ln()
        };
        let floor = best * (1.0 - 1e-9);
        let mut chosen: Option<(usize, f64)> = None;
        for side in [&mut above.iter(), &mut below.iter().rev()] as [&mut dyn Iterator<Item = &usize>; 2] {
            for &i in side {
                let g = &self.families[i];
                if mass_ratio(g) < floor {
                    break;
                }
                if healthy(i) && product(g) >= floor {
                    let s = score(g);
                    if chosen.is_none_or(|(c, cs)| s > cs || (s == cs && i > c)) {
                        chosen = Some((i, s));
                    }
                }
            }
        }
        chosen.map(|(i, _)| i)
    }

    /// (4.27): adds family k to family t, conserving particles and mass.
    /// Returns whether t's particles moved far enough (10⁻³ in mass or φ
    /// from those its properties and pair data were computed for), or its
    /// zoom factor changed, for its pair data and rates to be recomputed;
    /// otherwise its mass, φ and group count change and the cached
    /// properties and rates per pair are kept.
    fn merge_into(&mut self, k: usize, t: usize) -> bool {
        let a = self.families[k];
        self.merge_particles_into(a.body(), a.particles(), t)
    }

    /// (4.27) for `count` particles `body` added to family t (see [`Engine::merge_into`]).
    fn merge_particles_into(&mut self, body: Body, count: f64, t: usize) -> bool {
        let b = self.families[t];
        let g = count + b.particles();
        let mass = (body.mass * count + b.mass * b.particles()) / g;
        let filling = (body.filling * count + b.filling * b.particles()) / g;
        // The merged family keeps family t's zoom factor unless that would
        // give it more groups than a whole mass decade is meant to hold (w*,
        // 4.26): then it takes the smallest zoom factor that gives it at
        // most w*, the least that z*(m) (4.26) of a decade holding these
        // particles would be. A family of a few large bodies (z = 0) that
        // takes in many particles would otherwise count each as a group,
        // and multiply the rate of its events, each moving one particle,
        // by as much until the next re-zoom.
        let w_star = self.settings.groups_per_decade;
        let z = if g / exp2i(b.zoom) > w_star { b.zoom.max((g / w_star).log2().ceil() as i32) } else { b.zoom };
        self.tally.merges += 1;
        // Measured from the particles the cached data belong to, so that a
        // run of small merges cannot carry the family away from them.
        let at = self.cached[t];
        let moved = (mass / at.mass - 1.0).abs() > MERGE_REFRESH || (filling / at.filling - 1.0).abs() > MERGE_REFRESH;
        let props = if moved {
            self.cached[t] = Body { mass, filling };
            self.model.props(Body { mass, filling })
        } else {
            b.props
        };
        if mass != b.mass {
            self.unlist(t);
        }
        self.families[t] = Family { mass, filling, groups: g / exp2i(z), zoom: z, props };
        self.model.set_lane(&mut self.lanes, t, &self.families[t]);
        self.keys[t] = Key { mass, zoom: z };
        if mass != b.mass {
            self.enlist(t);
        }
        // A new zoom factor changes the family's unit rates: they are
        // computed afresh, with its pair data, once the merges are done.
        moved || z != b.zoom
    }

    /// Sets every family's zoom factor to z*(m) (4.26) and merges families
    /// that cannot fill one group at their zoom factor (4.27).
    pub fn rezoom(&mut self) {
        let decades = &mut self.decades;
        decades.clear();
        for f in &self.families {
            *decades.entry(decade_of(f.mass)).or_default() += f.particles();
        }
        for ((f, key), dirty) in self.families.iter_mut().zip(&mut self.keys).zip(self.dirty.iter_mut()) {
            let n10 = decades.get(&decade_of(f.mass)).copied().unwrap_or(0.0);
            let z = z_star(n10, f.mass, self.initial_mass, &self.settings);
            *dirty = z != f.zoom;
            if *dirty {
                f.groups = f.particles() / exp2i(z);
                f.zoom = z;
                key.zoom = z;
            }
        }
        self.watch_all = true;
        self.merge_small(false);
        // Rates change only for families whose zoom changed (merged ones were
        // refreshed as they merged). Now and then, and when many changed,
        // the partner sums are summed afresh so that they carry no
        // accumulated rounding (the unit rates themselves are always
        // computed afresh).
        self.tally.rezooms += 1;
        let changed = self.dirty.iter().filter(|d| **d).count();
        for k in 0..self.families.len() {
            if self.dirty[k] {
                self.refresh_rates(k);
            }
        }
        if self.tally.rezooms.is_multiple_of(32) || 4 * changed > self.families.len() {
            self.sum_afresh();
        }
        self.dirty.iter_mut().for_each(|d| *d = false);
        self.zoomed_at = self.moments();
        self.since_zoom = 0;
    }

    /// Whether what the engine keeps beside the families (each one's mass
    /// and zoom factor, and the model's lanes) matches them, and each
    /// family's mass and φ lie within `MERGE_REFRESH` of the particles its
    /// cached properties and pair data were computed for.
    #[cfg(test)]
    pub(crate) fn mirrors_match(&self) -> bool
    where
        M::Lanes: PartialEq,
    {
        let mut lanes = M::Lanes::default();
        for (i, f) in self.families.iter().enumerate() {
            self.model.set_lane(&mut lanes, i, f);
        }
        let near = |x: f64, at: f64| (x / at - 1.0).abs() <= MERGE_REFRESH;
        lanes == self.lanes
            && self.keys.len() == self.families.len()
            && self.keys.iter().zip(&self.families).all(|(k, f)| k.mass == f.mass && k.zoom == f.zoom)
            && self.cached.len() == self.families.len()
            && self.cached.iter().zip(&self.families).all(|(c, f)| near(f.mass, c.mass) && near(f.filling, c.filling))
    }

    /// Whether the rates are those of the cached pair data: every family is
    /// rated with its groups counted, every unit rate is the one its pair's
    /// data and the families' zoom factors give (and the same both ways),
    /// and every partner sum equals Σ_j w_j × unit rate summed afresh to
    /// within `tolerance` of the sum of its terms' sizes. Otherwise says
    /// where they differ.
    #[cfg(test)]
    pub(crate) fn rates_match(&self, tolerance: f64) -> Result<(), String> {
        let n = self.families.len();
        for (i, f) in self.families.iter().enumerate() {
            if !self.rated[i] || self.counted[i] != f.groups {
                return Err(format!(
                    "family {i}: rated {}, counted {} of {} groups",
                    self.rated[i], self.counted[i], f.groups
                ));
            }
            let mut sum = 0.0;
            let mut size = 0.0;
            for (j, g) in self.families.iter().enumerate() {
                let unit = self.units.get(i, j);
                let expected = if i == j { 0.0 } else { unit_of(f, i, g, j, &self.data(i, j)) };
                if unit.to_bits() != expected.to_bits() || unit.to_bits() != self.units.get(j, i).to_bits() {
                    return Err(format!(
                        "pair ({i}, {j}) of {n}: unit rate {unit}, mirror {}, from its data {expected}",
                        self.units.get(j, i)
                    ));
                }
                sum += g.groups * unit;
                size += (g.groups * unit).abs();
            }
            if (self.partner_sum[i] - sum).abs() > tolerance * size {
                return Err(format!("family {i} of {n}: partner sum {} against {sum} afresh", self.partner_sum[i]));
            }
        }
        Ok(())
    }

    /// Mass per unit volume per ln m in logarithmic bins, `per_decade` bins
    /// per decade: (bin centre, mass density per ln m).
    pub fn mass_spectrum(&self, per_decade: usize) -> Vec<(f64, f64)> {
        spectrum(self.families.iter().map(|f| (f.mass, f.mass * f.particles())), per_decade, self.volume)
    }
}

/// (m_a, m_p, m_max) of families given as (particles, mass), summed in their order.
fn moments_of(families: impl Iterator<Item = (f64, f64)>) -> (f64, f64, f64) {
    let (mut n, mut m1, mut m2, mut max) = (0.0, 0.0, 0.0, 0.0f64);
    for (g, mass) in families {
        n += g;
        m1 += g * mass;
        m2 += g * mass * mass;
        max = max.max(mass);
    }
    (m1 / n, m2 / m1, max)
}

/// Mass per volume per ln m in logarithmic bins from (mass, total mass) pairs.
pub fn spectrum(items: impl Iterator<Item = (f64, f64)>, per_decade: usize, volume: f64) -> Vec<(f64, f64)> {
    let mut bins: std::collections::BTreeMap<i64, f64> = std::collections::BTreeMap::new();
    let n = per_decade.max(1) as f64;
    for (m, total) in items {
        *bins.entry((m.log10() * n).floor() as i64).or_default() += total;
    }
    let width = std::f64::consts::LN_10 / n;
    bins.into_iter().map(|(b, m)| (10f64.powf((b as f64 + 0.5) / n), m / volume / width)).collect()
}

/// Whether family `a` (index i) is the pair's lo family, the one with the
/// lower zoom factor (ties: the more massive, then the lower index), and N_ε
/// of the pair (4.21)–(4.24) from the pair's cached headroom: 2^{z_lo}
/// lo-particles each meet 2^{z_hi − z_lo − N_ε} hi-particles in one event.
fn order_of<P>(a: &Family<P>, i: usize, b: &Family<P>, j: usize, headroom: f32) -> (bool, i32) {
    let lo_first = a.zoom < b.zoom || (a.zoom == b.zoom && (a.mass > b.mass || (a.mass == b.mass && i < j)));
    let (l, h) = if lo_first { (a, b) } else { (b, a) };
    let span = h.zoom - l.zoom;
    if span == 0 {
        return (lo_first, 0);
    }
    if l.mass < h.mass {
        // The lo-particles are the projectiles: one on one.
        return (lo_first, span);
    }
    // The headroom is an integer (or ±∞), so n needs no rounding up.
    let n = f64::from(span) - f64::from(headroom);
    let n_eps = if n.is_finite() { (n.max(0.0) as i32).min(span) } else { 0 };
    (lo_first, n_eps)
}

/// The group event rate (4.25) of pair (i, j) per group of each,
/// 2^{z_lo + N_ε} K/V, from its cached data (what [`unit_row`] computes
/// for a whole row).
#[cfg(test)]
fn unit_of<P>(a: &Family<P>, i: usize, b: &Family<P>, j: usize, pair: &Pair) -> f64 {
    if pair.c <= 0.0 {
        return 0.0;
    }
    let (lo_first, n_eps) = order_of(a, i, b, j, pair.headroom);
    let z_lo = if lo_first { a.zoom } else { b.zoom };
    exp2i(z_lo + n_eps) * pair.c
}

/// The unit rates of the lead family (zoom, mass, index) with every family
/// into `units` ([`unit_of`], 0 with itself), and every other family's
/// partner sum moved by the lead's group count now times the new unit rate
/// less its count before times the old one.
fn unit_row(
    lead: (i32, f64, usize),
    counts: (f64, f64),
    keys: &[Key],
    pairs: (&[f64], &[f32]),
    units: &mut [f64],
    sums: &mut [f64],
) {
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("avx512f") {
            // SAFETY: the processor has AVX-512F (checked just above).
            return unsafe { unit_row_avx512(lead, counts, keys, pairs, units, sums) };
        }
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the processor has AVX2 (checked just above).
            return unsafe { unit_row_avx2(lead, counts, keys, pairs, units, sums) };
        }
    }
    unit_row_lanes(lead, counts, keys, pairs, units, sums);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f")]
fn unit_row_avx512(
    lead: (i32, f64, usize),
    counts: (f64, f64),
    keys: &[Key],
    pairs: (&[f64], &[f32]),
    units: &mut [f64],
    sums: &mut [f64],
) {
    unit_row_lanes(lead, counts, keys, pairs, units, sums);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn unit_row_avx2(
    lead: (i32, f64, usize),
    counts: (f64, f64),
    keys: &[Key],
    pairs: (&[f64], &[f32]),
    units: &mut [f64],
    sums: &mut [f64],
) {
    unit_row_lanes(lead, counts, keys, pairs, units, sums);
}

/// [`unit_row`] without branches: [`order_of`] and [`unit_of`] with both
/// sides of every choice computed and one kept (the same numbers). With
/// equal zoom factors N_ε is 0 whichever family is lo, so the order of the
/// pair matters only through the lower zoom factor and whether its family
/// is the lighter one.
#[inline(always)]
fn unit_row_lanes(
    (zk, mk, k): (i32, f64, usize),
    (now, before): (f64, f64),
    keys: &[Key],
    pairs: (&[f64], &[f32]),
    units: &mut [f64],
    sums: &mut [f64],
) {
    let n = units.len();
    let (keys, rates, headrooms, sums) = (&keys[..n], &pairs.0[..n], &pairs.1[..n], &mut sums[..n]);
    for j in 0..n {
        let Key { mass: mj, zoom: zj } = keys[j];
        let (c, headroom) = (rates[j], headrooms[j]);
        let span = (zk - zj).abs();
        let zl = zk.min(zj);
        let lighter_lo = if zk < zj { mk < mj } else { mj < mk };
        let short = f64::from(span) - f64::from(headroom);
        // The headroom is an integer or ±∞: within [0, span] `short` is an
        // exact integer, and ±∞ gives 0.
        let clamped = if short == f64::INFINITY { 0.0 } else { short.max(0.0).min(f64::from(span)) };
        // SAFETY: `clamped` is finite and within [0, span], an i32.
        let general = unsafe { clamped.to_int_unchecked::<i32>() };
        let n_eps = if span == 0 {
            0
        } else if lighter_lo {
            span
        } else {
            general
        };
        // exp2i(zl + N_ε) from its bits: 2^e for −1022 ≤ e ≤ 1023, 0 below
        // (e = −1023) and ∞ above (e = 1024).
        let e = (zl + n_eps).clamp(-1023, 1024);
        let unit = if c <= 0.0 || j == k { 0.0 } else { f64::from_bits(((e + 1023) as u64) << 52) * c };
        let old = units[j];
        units[j] = unit;
        let moved = now * unit - before * old;
        sums[j] += if j == k { 0.0 } else { moved };
    }
}

/// How an event made a product.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Made {
    /// By sticking (or returned unchanged by a bounce).
    Stuck,
    /// By erosion: the remnant of the target.
    Broken,
    /// By erosion or shattering: fragments. They take the zoom factor of
    /// their mass decade where that is larger (see [`Engine::decade_zoom`]).
    Fragments,
}

/// A family's mass and zoom factor.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Key {
    mass: f64,
    zoom: i32,
}

/// Particles made by one event: what they are, how many, at which zoom factor.
type Product = (Body, f64, i32, Made);

/// A merge that moves a family's mass or filling factor by less than this
/// keeps its cached properties and pair data.
const MERGE_REFRESH: f64 = 1e-3;

/// ⌊log₂ x⌋ for x > 0, read off the binary exponent where x is a normal
/// number (exact, and far cheaper than a logarithm); N_ε (4.24) needs no
/// more than this.
pub(crate) fn floor_log2(x: f64) -> f64 {
    let biased = ((x.to_bits() >> 52) & 0x7ff) as i32;
    if x > 0.0 && biased != 0 && biased != 0x7ff { f64::from(biased - 1023) } else { x.log2().floor() }
}

/// Families with fewer than one group merge only into a family within this
/// mass factor; otherwise they are magnified.
const MERGE_RATIO: f64 = f64::INFINITY;

/// 2^k for an integer k, exactly (0 below the smallest normal, ∞ above the largest).
fn exp2i(k: i32) -> f64 {
    if k < -1022 {
        0.0
    } else if k > 1023 {
        f64::INFINITY
    } else {
        f64::from_bits(((1023 + k) as u64) << 52)
    }
}

/// [`exp2i`] without a branch: the exponent clamped to where 2^k is 0 or ∞.
#[inline(always)]
fn exp2i_clamped(k: i32) -> f64 {
    f64::from_bits(((1023 + k.clamp(-1023, 1024)) as u64) << 52)
}

/// z* = [log₂(N₁₀/w*)] ≥ 0 (4.26).
/// The largest zoom factor at which one group of particles of mass `m`
/// holds at most `cap` of the total mass `total` (no limit for `cap` ≥ 1).
fn capped_zoom(m: f64, total: f64, cap: f64) -> i32 {
    if cap >= 1.0 { i32::MAX } else { (cap * total / m).log2().floor().max(0.0) as i32 }
}

/// The mass decade of particles of mass m, ⌊log₁₀ m⌋.
fn decade_of(mass: f64) -> i64 {
    mass.log10().floor() as i64
}

/// z*(m) (4.26) of particles of mass m whose decade holds `n10` particles,
/// capped by the group mass cap ε_M (of a column of `total` mass).
fn z_star(n10: f64, mass: f64, total: f64, settings: &Settings) -> i32 {
    zoom_for(n10, settings.groups_per_decade).min(capped_zoom(mass, total, settings.group_mass_cap))
}

fn zoom_for(n10: f64, w_star: f64) -> i32 {
    if n10 <= w_star { 0 } else { (n10 / w_star).log2().floor() as i32 }
}

/// Index whose cumulative weight first exceeds `target` (the last positive one otherwise).
fn pick(weights: &[f64], target: f64) -> usize {
    cumulative_pick(&weights, target, 0)
}

/// Partial sums kept side by side in the scans of an event. One running sum
/// waits on the latency of every addition (four cycles, for some 500
/// families every event, several times); this many independent ones overlap.
const CHAINS: usize = 8;

/// a₀ + … + a₇, pairwise.
#[inline(always)]
fn pairwise(a: [f64; CHAINS]) -> f64 {
    ((a[0] + a[1]) + (a[2] + a[3])) + ((a[4] + a[5]) + (a[6] + a[7]))
}

/// Σ xᵢ in [`CHAINS`] interleaved partial sums, added pairwise, then the tail in order.
fn sum_in_chains(xs: &[f64]) -> f64 {
    let chunks = xs.chunks_exact(CHAINS);
    let tail = chunks.remainder();
    let mut acc = [0.0; CHAINS];
    for c in chunks {
        for (a, x) in acc.iter_mut().zip(c) {
            *a += x;
        }
    }
    tail.iter().fold(pairwise(acc), |s, x| s + x)
}

/// Σ a_i b_i in [`CHAINS`] interleaved partial sums, added pairwise, then the tail in order.
fn dot_in_chains(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let (ca, cb) = (a.chunks_exact(CHAINS), b.chunks_exact(CHAINS));
    let tail = ca.remainder().iter().zip(cb.remainder());
    let mut acc = [0.0; CHAINS];
    for (xa, xb) in ca.zip(cb) {
        for ((s, x), y) in acc.iter_mut().zip(xa).zip(xb) {
            *s += x * y;
        }
    }
    tail.fold(pairwise(acc), |s, (x, y)| s + x * y)
}

/// (m_a, m_p, m_max) of families given by their keys (mass, zoom factor) and
/// group counts, in four interleaved partial sums of each moment.
fn moments_in_chains(keys: &[Key], groups: &[f64]) -> (f64, f64, f64) {
    const L: usize = 4;
    let n = keys.len().min(groups.len());
    let (keys, groups) = (&keys[..n], &groups[..n]);
    let (mut c, mut m1, mut m2, mut max) = ([0.0; L], [0.0; L], [0.0; L], [0.0f64; L]);
    let (ck, cg) = (keys.chunks_exact(L), groups.chunks_exact(L));
    let tail = ck.remainder().iter().zip(cg.remainder());
    for (ks, gs) in ck.zip(cg) {
        for l in 0..L {
            let (g, mass) = (gs[l] * exp2i_clamped(ks[l].zoom), ks[l].mass);
            c[l] += g;
            m1[l] += g * mass;
            m2[l] += g * mass * mass;
            max[l] = max[l].max(mass);
        }
    }
    let (mut c, mut m1, mut m2) =
        ((c[0] + c[1]) + (c[2] + c[3]), (m1[0] + m1[1]) + (m1[2] + m1[3]), (m2[0] + m2[1]) + (m2[2] + m2[3]));
    let mut max = max[0].max(max[1]).max(max[2].max(max[3]));
    for (key, groups) in tail {
        let g = groups * exp2i_clamped(key.zoom);
        c += g;
        m1 += g * key.mass;
        m2 += g * key.mass * key.mass;
        max = max.max(key.mass);
    }
    (m1 / c, m2 / m1, max)
}

/// Weights read in blocks of [`CHAINS`] (see [`cumulative_pick`]).
trait Weights {
    /// The number of weights.
    fn len(&self) -> usize;
    /// Weight j.
    fn at(&self, j: usize) -> f64;
    /// Weights base..base + CHAINS (all within the length).
    fn block(&self, base: usize) -> [f64; CHAINS];
}

impl Weights for &[f64] {
    fn len(&self) -> usize {
        <[f64]>::len(self)
    }
    fn at(&self, j: usize) -> f64 {
        self[j]
    }
    #[inline(always)]
    fn block(&self, base: usize) -> [f64; CHAINS] {
        let b = &self[base..base + CHAINS];
        std::array::from_fn(|l| b[l])
    }
}

/// Weights a_j b_j of two slices of one length.
struct Products<'a>(&'a [f64], &'a [f64]);

impl Weights for Products<'_> {
    fn len(&self) -> usize {
        self.0.len().min(self.1.len())
    }
    fn at(&self, j: usize) -> f64 {
        self.0[j] * self.1[j]
    }
    #[inline(always)]
    fn block(&self, base: usize) -> [f64; CHAINS] {
        let (a, b) = (&self.0[base..base + CHAINS], &self.1[base..base + CHAINS]);
        std::array::from_fn(|l| a[l] * b[l])
    }
}

/// Index whose cumulative weight, over the positive weights alone, first
/// exceeds `target`; the last positive one if none does (rounding), `none` if
/// no weight is positive. Whole blocks of [`CHAINS`] weights whose sum does
/// not reach the target are passed over by that sum (independent additions);
/// the block that may reach it is walked weight by weight.
#[inline(always)]
fn cumulative_pick(w: &impl Weights, target: f64, none: usize) -> usize {
    let positive = |x: f64| if x > 0.0 { x } else { 0.0 };
    let n = w.len();
    let mut acc = 0.0;
    let mut base = 0;
    while base + CHAINS <= n {
        let block = w.block(base).map(positive);
        let s = pairwise(block);
        if acc + s > target {
            for (l, &x) in block.iter().enumerate() {
                if x > 0.0 {
                    acc += x;
                    if acc > target {
                        return base + l;
                    }
                }
            }
        } else {
            acc += s;
        }
        base += CHAINS;
    }
    for j in base..n {
        let x = w.at(j);
        if x > 0.0 {
            acc += x;
            if acc > target {
                return j;
            }
        }
    }
    (0..n).rev().find(|&j| w.at(j) > 0.0).unwrap_or(none)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A model whose pair data say the pair sticks (so that a sequence may
    /// extrapolate one collision to several) and whose collisions do as set.
    struct Toy(Collision);

    impl Model for Toy {
        type Props = ();
        type Lanes = ();
        fn props(&self, _: Body) {}
        fn rate(&self, _: &Family<()>, _: &Family<()>) -> f64 {
            1.0
        }
        fn collide(&self, _: &Family<()>, _: &Family<()>) -> Collision {
            self.0
        }
        fn pair(&self, _: &Family<()>, _: &Family<()>) -> (f64, Effect) {
            (1.0, Effect::Stick { change: 0.0 })
        }
    }

    /// Every outcome of a group event keeps the mass that went in, also
    /// where a target meeting several projectiles in sequence shatters at
    /// the first (before, the other projectiles' mass was lost: 5 × 10⁻⁴ of
    /// a column's mass in one event at v_frag = 33.29 m/s).
    #[test]
    fn a_row_of_unit_rates_equals_them_one_at_a_time() {
        use rand::Rng;
        let mut rng = rand::rngs::StdRng::seed_from_u64(3);
        let n = 300;
        let family = |mass: f64, zoom: i32| Family { mass, filling: 1.0, groups: 1.0, zoom, props: () };
        // Few masses and zooms, so that ties in both are common.
        let families: Vec<Family<()>> =
            (0..n).map(|_| family(f64::from(rng.random_range(1..6)), rng.random_range(0..5))).collect();
        let keys: Vec<Key> = families.iter().map(|f| Key { mass: f.mass, zoom: f.zoom }).collect();
        let headrooms = [f32::INFINITY, f32::NEG_INFINITY, -3.0, 0.0, 1.0, 2.0, 7.0];
        let pairs: Vec<Pair> = (0..n)
            .map(|j| Pair {
                c: if j % 7 == 0 { 0.0 } else { rng.random_range(0.1..10.0) },
                headroom: headrooms[j % headrooms.len()],
            })
            .collect();
        let rates: Vec<f64> = pairs.iter().map(|p| p.c).collect();
        let heads: Vec<f32> = pairs.iter().map(|p| p.headroom).collect();
        for k in [0, 1, 17, 150, n - 1] {
            let fk = &families[k];
            let mut units: Vec<f64> = (0..n).map(|j| if j == k { 0.0 } else { rng.random_range(0.0..1.0) }).collect();
            let old = units.clone();
            let mut sums: Vec<f64> = (0..n).map(|_| rng.random_range(0.0..100.0)).collect();
            let before = sums.clone();
            let (now, then) = (3.0, 2.5);
            unit_row((fk.zoom, fk.mass, k), (now, then), &keys, (&rates, &heads), &mut units, &mut sums);
            for j in 0..n {
                let unit = if j == k { 0.0 } else { unit_of(fk, k, &families[j], j, &pairs[j]) };
                assert_eq!(units[j].to_bits(), unit.to_bits(), "pair {k}, {j}");
                let sum = if j == k { before[j] } else { before[j] + (now * unit - then * old[j]) };
                assert_eq!(sums[j].to_bits(), sum.to_bits(), "sum {j}");
            }
        }
    }

    /// Fragments made in a mass decade that the last re-zoom found well
    /// populated take its zoom factor z*(m) (4.26) and, filling less than
    /// one group there, merge as they are made (the next re-zoom would
    /// merge them unused); in an empty decade, and for a remnant, they
    /// start a family of one group as before.
    #[test]
    fn fragments_take_the_zoom_factor_of_their_decade() {
        let fragment = Body { mass: 0.5, filling: 1.0 };
        let collision = Collision::Erode { loss: 1.0, fragment, count: 16.0 };
        let first = Body { mass: 1.0, filling: 0.5 };
        let mut e = Engine::new(Toy(collision), first, 1e6, 1.0, Settings::default()).expect("engine");
        e.rezoom();
        // 10⁶ particles of mass 1 in their decade: z* = ⌊log₂(10⁶/60)⌋ = 14.
        assert_eq!(e.families()[0].zoom, 14);
        let mass = |e: &Engine<Toy>| e.families().iter().map(|f| f.mass * f.particles()).sum::<f64>();
        let before = mass(&e);
        // 16 fragments of mass 2 (the populated decade): they merge.
        let near = Body { mass: 2.0, filling: 0.5 };
        e.add_product(near, 16.0, 4, Made::Fragments);
        e.tidy();
        assert_eq!(e.families().len(), 1);
        assert!((mass(&e) / (before + 32.0) - 1.0).abs() < 1e-14);
        // 16 fragments of mass 0.05 (an empty decade): one group at z = 4.
        e.add_product(Body { mass: 0.05, filling: 0.5 }, 16.0, 4, Made::Fragments);
        e.tidy();
        assert_eq!(e.families().len(), 2);
        assert_eq!((e.families()[1].zoom, e.families()[1].groups), (4, 1.0));
        // A remnant of mass 2 keeps the zoom factor it was made at.
        e.add_product(near, 16.0, 4, Made::Broken);
        e.tidy();
        assert_eq!(e.families().len(), 3);
        assert_eq!((e.families()[2].zoom, e.families()[2].groups), (4, 1.0));
    }

    #[test]
    fn every_outcome_of_a_sequence_keeps_the_mass() {
        let fragment = Body { mass: 0.5, filling: 1.0 };
        for collision in [
            Collision::Stick { change: -0.1 },
            Collision::Erode { loss: 2.0, fragment, count: 16.0 },
            Collision::Shatter { fragment, count: 212.0 },
            Collision::Bounce,
        ] {
            let first = Body { mass: 1.0, filling: 0.5 };
            let mut e = Engine::new(Toy(collision), first, 1e6, 1.0, Settings::default()).expect("engine");
            let family = |mass: f64, zoom: i32| Family { mass, filling: 0.5, groups: 4.0, zoom, props: () };
            // lo: the target, 2³ particles a group; hi: projectiles of mass
            // 6, 2⁶ a group, 8 of them met by each target particle.
            let (lo, hi) = (family(100.0, 3), family(6.0, 6));
            let (per, units) = (8.0, 8.0);
            let mut made = Vec::new();
            e.outcome(&lo, &hi, per, units, lo.zoom, &mut made);
            let out: f64 = made.iter().map(|(b, n, _, _)| b.mass * n).sum();
            let into = units * (lo.mass + per * hi.mass);
            assert!((out / into - 1.0).abs() < 1e-12, "{collision:?}: {out} out of {into}: {made:?}");
        }
    }

    /// N_ε's ⌊log₂(f x/dx)⌋ read off exponents and significands is the floor
    /// of the exact ratio: 2^h ≤ f x/dx < 2^{h+1}, checked by products with
    /// powers of two (exact), over ratios of either order, exact powers of
    /// two and significands that tie.
    #[test]
    fn the_headroom_is_the_floor_of_the_exact_ratio() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(11);
        let mut cases: Vec<(f64, f64)> = (0..20_000)
            .map(|_| (10f64.powf(rng.random_range(-30.0..30.0)), 10f64.powf(rng.random_range(-30.0..30.0))))
            .collect();
        cases.extend([
            (1.0, 1.0),
            (8.0, 2.0),
            (3.0, 1.5),
            (1.5, 3.0),
            (1.0, 1.0 + f64::EPSILON),
            (1.0 + f64::EPSILON, 1.0),
        ]);
        for (fx, dx) in cases {
            let h = room(1.0, fx, dx);
            assert_eq!(h, h.trunc(), "{fx} / {dx}");
            let p = exp2i(h as i32);
            assert!(dx * p <= fx && fx < dx * 2.0 * p, "{fx} / {dx}: {h}");
        }
        assert_eq!(room(0.1, 1.0, 0.0), f64::INFINITY);
        // Off the normal numbers it is the rounded ratio's.
        assert_eq!(room(1.0, 1.0, 1e-310), floor_log2(1.0 / 1e-310));
    }

    /// The draw over blocks of weights picks what one running sum picks,
    /// except where the target lies within rounding of a boundary; with
    /// nothing left to exceed, the last positive weight; with no positive
    /// weight, the fallback. Sums in chains are the sum to rounding.
    #[test]
    fn a_draw_by_blocks_picks_what_a_running_sum_picks() {
        use rand::{Rng, SeedableRng};
        let running = |w: &[f64], target: f64, none: usize| {
            let (mut acc, mut last) = (0.0, none);
            for (k, &x) in w.iter().enumerate() {
                if x > 0.0 {
                    acc += x;
                    last = k;
                    if acc > target {
                        return k;
                    }
                }
            }
            last
        };
        let mut rng = rand::rngs::StdRng::seed_from_u64(12);
        for round in 0..2000 {
            let n = rng.random_range(0..80);
            let w: Vec<f64> = (0..n)
                .map(|_| match rng.random_range(0..6) {
                    0 => 0.0,
                    1 => -rng.random::<f64>(),
                    _ => 10f64.powf(rng.random_range(-6.0..6.0)),
                })
                .collect();
            let b: Vec<f64> = (0..n).map(|_| rng.random_range(0.5..2.0)).collect();
            let total: f64 = w.iter().filter(|x| **x > 0.0).sum();
            let products: Vec<f64> = w.iter().zip(&b).map(|(x, y)| x * y).collect();
            let product_total: f64 = products.iter().filter(|x| **x > 0.0).sum();
            for _ in 0..20 {
                let u = rng.random::<f64>() * 1.01;
                let near_boundary = |w: &[f64], target: f64| {
                    let mut acc = 0.0;
                    w.iter().filter(|x| **x > 0.0).any(|x| {
                        acc += x;
                        (acc - target).abs() <= 1e-12 * acc
                    })
                };
                if !near_boundary(&w, u * total) {
                    assert_eq!(pick(&w, u * total), running(&w, u * total, 0), "round {round}: {w:?} at {u}");
                }
                if !near_boundary(&products, u * product_total) {
                    let blocks = cumulative_pick(&Products(&w, &b), u * product_total, 3);
                    assert_eq!(blocks, running(&products, u * product_total, 3), "round {round}");
                }
            }
            let sequential: f64 = w.iter().sum();
            let scale: f64 = w.iter().map(|x| x.abs()).sum();
            assert!((sum_in_chains(&w) - sequential).abs() <= 1e-14 * scale, "round {round}");
            let dot: f64 = w.iter().zip(&b).map(|(x, y)| x * y).sum();
            let dot_scale: f64 = w.iter().zip(&b).map(|(x, y)| (x * y).abs()).sum();
            assert!((dot_in_chains(&w, &b) - dot).abs() <= 1e-14 * dot_scale, "round {round}");
        }
        assert_eq!(pick(&[0.0, -1.0, 0.0], 0.5), 0);
        assert_eq!(cumulative_pick(&Products(&[0.0; 9], &[1.0; 9]), 0.5, 7), 7);
    }

    /// The moments in chains are the moments summed in order, to rounding.
    #[test]
    fn moments_in_chains_equal_the_moments_in_order() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(13);
        for _ in 0..200 {
            let n = rng.random_range(1..50);
            let keys: Vec<Key> = (0..n)
                .map(|_| Key { mass: 10f64.powf(rng.random_range(-15.0..10.0)), zoom: rng.random_range(0..60) })
                .collect();
            let groups: Vec<f64> = (0..n).map(|_| rng.random_range(0.0..100.0)).collect();
            let (a, p, m) = moments_in_chains(&keys, &groups);
            let (a0, p0, m0) = moments_of(keys.iter().zip(&groups).map(|(k, g)| (g * exp2i(k.zoom), k.mass)));
            assert_eq!(m, m0);
            assert!((a / a0 - 1.0).abs() < 1e-13 && (p / p0 - 1.0).abs() < 1e-13, "{a} {a0} {p} {p0}");
        }
        for k in [-2000, -1075, -1023, -1022, 0, 1, 1023, 1024, 5000] {
            assert_eq!(exp2i_clamped(k).to_bits(), exp2i(k).to_bits(), "2^{k}");
        }
    }
}
