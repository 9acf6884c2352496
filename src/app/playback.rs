//! Playing a scene's history: play, pause, step, speed, loop and a
//! scrubber over the time cursor. Playback moves only the cursor (a styling
//! parameter), so it never recomputes the model.

/// Playback speeds offered, as multiples of the normal pace.
pub const SPEEDS: [f64; 7] = [0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0];

/// Seconds a whole history takes at 1×.
pub const RUN_SECONDS: f64 = 12.0;

/// Fraction of the history one step moves.
pub const STEP: f64 = 0.01;

/// The state of the transport.
#[derive(Debug, Clone, PartialEq)]
pub struct Playback {
    /// Whether the history is playing.
    pub playing: bool,
    /// Speed, a member of [`SPEEDS`].
    pub speed: f64,
    /// Whether playing starts over at the end.
    pub looping: bool,
}

impl Default for Playback {
    fn default() -> Self {
        Playback { playing: false, speed: 1.0, looping: false }
    }
}

impl Playback {
    /// The cursor after `dt` seconds of play from `fraction`; at the end it
    /// starts over when looping and stops otherwise.
    pub fn advance(&mut self, fraction: f64, dt: f64) -> f64 {
        if !self.playing {
            return fraction;
        }
        let next = fraction + dt.clamp(0.0, 0.25) * self.speed / RUN_SECONDS;
        if next < 1.0 {
            next
        } else if self.looping {
            next.fract()
        } else {
            self.playing = false;
            1.0
        }
    }

    /// Starts or pauses; playing from the end starts over.
    pub fn toggle(&mut self, fraction: &mut f64) {
        self.playing = !self.playing;
        if self.playing && *fraction >= 1.0 {
            *fraction = 0.0;
        }
    }
}

/// The cursor moved `by` steps, kept within the history.
pub fn step(fraction: f64, by: f64) -> f64 {
    (fraction + by * STEP).clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A run plays through in RUN_SECONDS / speed, then stops at the end
    /// or starts over when looping.
    #[test]
    fn playing_reaches_the_end_in_its_time() {
        let mut p = Playback { playing: true, speed: 4.0, looping: false };
        let mut f = 0.0;
        let dt = 1.0 / 60.0;
        let mut frames = 0;
        while p.playing && frames < 10_000 {
            f = p.advance(f, dt);
            frames += 1;
        }
        let expected = RUN_SECONDS / 4.0 / dt;
        assert!((frames as f64 - expected).abs() <= 1.0, "{frames} frames, expected {expected}");
        assert_eq!(f, 1.0, "stops at the end");
        assert_eq!(p.advance(f, dt), 1.0, "paused stays");
        p.toggle(&mut f);
        assert!(p.playing && f == 0.0, "playing from the end starts over");
        let mut looped = Playback { playing: true, speed: 16.0, looping: true };
        let g = looped.advance(0.99, 0.1);
        assert!(looped.playing && g < 0.2, "{g}");
        assert_eq!(step(0.995, 1.0), 1.0);
        assert_eq!(step(0.0, -1.0), 0.0);
    }
}
