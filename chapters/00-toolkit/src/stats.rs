//! Render statistics: how many rays of each kind, and why paths ended.

use std::fmt;
use std::ops::Add;

/// Counts gathered while rendering. Every chapter counts the rays it traces;
/// later chapters fill in more of the fields.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Rays from the eye through the pixels (chapter 1).
    pub primary: u64,
    /// Rays from a hit point towards a light (chapter 4).
    pub shadow: u64,
    /// Mirror rays (chapter 5).
    pub reflection: u64,
    /// Transmitted rays (chapter 6).
    pub refraction: u64,
    /// Paths that ended because a ray hit nothing (chapter 7).
    pub ended_no_hit: u64,
    /// Paths that ended at the maximum depth (chapter 7).
    pub ended_max_depth: u64,
    /// Paths that ended because their weight fell below the threshold (chapter 7).
    pub ended_threshold: u64,
}

impl Stats {
    /// All rays traced, of every kind.
    pub fn rays(&self) -> u64 {
        self.primary + self.shadow + self.reflection + self.refraction
    }
}

impl Add for Stats {
    type Output = Stats;
    fn add(self, o: Stats) -> Stats {
        Stats {
            primary: self.primary + o.primary,
            shadow: self.shadow + o.shadow,
            reflection: self.reflection + o.reflection,
            refraction: self.refraction + o.refraction,
            ended_no_hit: self.ended_no_hit + o.ended_no_hit,
            ended_max_depth: self.ended_max_depth + o.ended_max_depth,
            ended_threshold: self.ended_threshold + o.ended_threshold,
        }
    }
}

impl fmt::Display for Stats {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} rays: {} primary, {} shadow, {} reflection, {} refraction",
            self.rays(),
            self.primary,
            self.shadow,
            self.reflection,
            self.refraction
        )?;
        let ended = self.ended_no_hit + self.ended_max_depth + self.ended_threshold;
        if ended > 0 {
            write!(
                f,
                "\npaths ended: {} by no hit, {} by maximum depth, {} by weight threshold",
                self.ended_no_hit, self.ended_max_depth, self.ended_threshold
            )?;
        }
        Ok(())
    }
}
