use grainscope::physics::aggregate::{Monomer, Thresholds, TurbulenceModel};
use grainscope::physics::coagulation::{Column, Compaction, RunConfig};
use grainscope::physics::constants::{AU, YEAR};
use grainscope::physics::disk::GasDisk;
use grainscope::physics::monte_carlo::Settings;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let v_eros: f64 = args.get(1).and_then(|v| v.parse().ok()).unwrap_or(1e4);
    let t_end: f64 = args.get(2).and_then(|v| v.parse().ok()).unwrap_or(1e4);
    let w: f64 = args.get(3).and_then(|v| v.parse().ok()).unwrap_or(40.0);
    let full = args.get(4).map(|v| v == "full").unwrap_or(true);
    let disk = GasDisk::mmsn(1e-3, 0.01);
    let column = Column {
        env: disk.local(5.0 * AU),
        monomer: Monomer::ice(),
        thresholds: Thresholds { v_frag: 80.0, v_eros, v_bounce: f64::INFINITY, r_crit: 1e-2 },
        c1: 1.0,
        compaction: if full { Compaction::Full } else { Compaction::Collisional },
        turbulence: TurbulenceModel::Thesis,
        epsilon: 0.1,
        newton: full,
    };
    let cfg = RunConfig {
        column,
        column_mass: 1e21,
        settings: Settings { groups_per_decade: w, ..Settings::default() },
        snapshots: vec![t_end * YEAR],
        history_per_decade: 4,
        max_events: 50_000_000,
        stop_mass: 1e12,
    };
    let start = std::time::Instant::now();
    let last = std::sync::Mutex::new(0.0f64);
    let run = cfg
        .run(1, &|f| {
            let mut l = last.lock().unwrap();
            if f > *l + 0.02 {
                *l = f;
                eprintln!("{:.0}% at {:.1} s", f * 100.0, start.elapsed().as_secs_f64());
            }
            true
        })
        .unwrap();
    let el = start.elapsed().as_secs_f64();
    for s in &run.history {
        println!(
            "t {:9.3e} yr ev {:8} fam {:5} m_p {:9.3e} g phi_p {:9.3e} m_max {:9.3e} g St_max {:9.3e} St_p {:9.3e} zeta {:6.3} t_drift {:9.3e} yr dM {:.1e}",
            s.t / YEAR,
            s.events,
            s.families,
            s.m_p * 1e3,
            s.phi_p,
            s.m_max * 1e3,
            s.stokes_max,
            s.stokes_p,
            s.zeta,
            s.t_drift / YEAR,
            s.mass_error
        );
    }
    println!(
        "{} events in {:.2} s ({:.0}/s), ended: {}, {:?}",
        run.events,
        el,
        run.events as f64 / el,
        run.ended,
        run.tally
    );
}
