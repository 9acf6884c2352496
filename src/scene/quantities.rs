//! Physical quantities that several scenes share, each declared once: its
//! key, unit, valid range and slider. A scene takes one with its own default
//! (`.default(d.field)`) and, where the context asks for it, its own label or
//! wording (`.labelled`, `.doc`); the unit and range stay those given here.

use super::controls::Control;

/// Fragmentation velocity v_frag (4.12): similar-size collisions above it fragment.
pub fn v_frag(value: &mut f64) -> Control<'_> {
    Control::number("v_frag", "fragmentation velocity", value)
        .unit("m s^-1")
        .shown("m/s", 1.0)
        .range(0.1, 1e4)
        .log()
        .doc("similar-size collisions above it fragment (80 m/s for 0.1 µm ice; 1e4: none)")
}

/// Erosion threshold v_eros (Sect. 4.2.3): small projectiles above it erode the target.
pub fn v_eros(value: &mut f64) -> Control<'_> {
    Control::number("v_eros", "erosion threshold", value)
        .unit("m s^-1")
        .shown("m/s", 1.0)
        .range(1e-3, 1e4)
        .log()
        .doc("projectiles below R_crit = 10⁻² of the target's mass erode above it (1e4: none)")
}

/// Combined surface energy γ of a contact (2γ_L for like materials).
pub fn surface_energy(value: &mut f64) -> Control<'_> {
    Control::number("surface_energy", "surface energy γ", value)
        .unit("J m^-2")
        .shown("J/m²", 1.0)
        .range(1e-3, 10.0)
        .log()
        .doc("combined surface energy of the contact (2γ_L for like materials)")
}

/// Range of the surface forces z₀ (σ₀ = γ/z₀).
pub fn force_range(value: &mut f64) -> Control<'_> {
    Control::number("z0", "force range z₀", value)
        .unit("m")
        .shown("nm", 1e9)
        .range(1e-10, 1e-9)
        .doc("range of surface forces")
}

/// Relative tolerance of the collision integrator.
pub fn solver_tolerance(value: &mut f64) -> Control<'_> {
    Control::number("rtol", "solver tolerance", value)
        .range(1e-12, 1e-3)
        .log()
        .doc("relative tolerance of the integrator (smaller: more accurate, slower)")
        .numerical()
}

/// A time cursor over a computed history, as a fraction of the run (styling only).
pub fn time_cursor(value: &mut f64) -> Control<'_> {
    Control::number("cursor", "time cursor", value).range(0.0, 1.0).doc("time of the marker, as a fraction of the run")
}

/// Groups per decade w* of the Monte Carlo distribution method (4.26).
pub fn groups_per_decade(value: &mut f64) -> Control<'_> {
    Control::number("groups_per_decade", "groups per decade w*", value)
        .range(5.0, 400.0)
        .log()
        .doc("resolution of the distribution method (4.26); the cost grows as about w*²")
        .numerical()
}

/// Mass of a power-law gas disk (5.1).
pub fn disk_mass(value: &mut f64) -> Control<'_> {
    Control::number("disk_mass", "disk mass", value).unit("M_sun").range(1e-4, 0.5).log().doc("mass of the gas disk")
}

/// The largest aggregate mass of a mass axis, in monomer masses.
pub fn max_monomers(value: &mut f64) -> Control<'_> {
    Control::number("max_monomers", "largest m/m₀", value).range(1e3, 1e34).log().doc("end of the mass axis")
}

/// Quality factor Q of the bulk losses of a rolling contact (3.22).
pub fn quality_factor(value: &mut f64) -> Control<'_> {
    Control::number("q", "quality factor Q", value).range(1.0, 1e12).log().doc("bulk losses (3.22)")
}

/// Efficiency η: the fraction of the kinetic energy that makes new surface (Sect. 6.2).
pub fn efficiency(value: &mut f64) -> Control<'_> {
    Control::number("eta", "efficiency η", value)
        .range(1e-6, 1.0)
        .log()
        .doc("fraction of the kinetic energy that makes surface")
}

/// Time a model is followed.
pub fn duration(value: &mut f64) -> Control<'_> {
    Control::number("duration_yr", "duration", value).unit("yr").range(1e2, 1e8).log().doc("time followed")
}

/// Adhesion hysteresis Δγ/γ: sets the critical rolling displacement
/// ξ_crit = (a_eq/12)(Δγ/γ) (3.16).
pub fn hysteresis(value: &mut f64) -> Control<'_> {
    Control::number("hysteresis", "hysteresis Δγ/γ", value).range(1e-3, 100.0).log().doc("sets ξ_crit (3.16)")
}

/// Radius in the disk, AU (the field's doc says what sits there).
pub fn disk_radius(value: &mut f64) -> Control<'_> {
    Control::number("radius_au", "disk radius", value).unit("AU").range(0.5, 300.0).log()
}
