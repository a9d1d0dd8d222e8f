//! How far the search is and how long is left, at a steady pace: a search of thousands of
//! candidates must not print a line per candidate into a CI log, nor stay silent for an hour.
//!
//! [`Pacer`] is pure (it is handed the elapsed time), so its pacing is tested with a fake clock.

use std::time::Duration;

/// Candidates done before the first estimate of the time left: enough that both threads of a
/// 2-core machine have finished a few (rayon starts them at different ends of the grid).
pub const FIRST_FEW: usize = 8;
/// Least time between two lines, but for the first estimate and the last line.
pub const MIN_GAP: Duration = Duration::from_secs(2);
/// Most time between two lines while candidates finish, even without a tenth more done.
pub const MAX_GAP: Duration = Duration::from_secs(10);

/// Decides when the search reports, and what.
#[derive(Clone, Debug)]
pub struct Pacer {
    total: usize,
    done: usize,
    /// When the last line was due, and the tenth of the search done then.
    last: Option<(Duration, usize)>,
}

/// One report: how many of how many, after how long, and the time left (once estimated).
#[derive(Clone, Debug, PartialEq)]
pub struct Line {
    /// Candidates done.
    pub done: usize,
    /// Candidates in all.
    pub total: usize,
    /// Time since the first candidate started.
    pub elapsed: Duration,
    /// Estimated time left, from the rate so far; `None` before [`FIRST_FEW`] are done or at the end.
    pub left: Option<Duration>,
}

impl Pacer {
    /// A search of `total` candidates, none done.
    pub fn new(total: usize) -> Self {
        Pacer {
            total,
            done: 0,
            last: None,
        }
    }

    /// Records `finished` more candidates done `elapsed` after the start; the line to print, when
    /// one is due: the first estimate (after [`FIRST_FEW`]), the end, and in between a line per
    /// tenth of the search at most every [`MIN_GAP`], or every [`MAX_GAP`] when tenths are slow.
    pub fn advance(&mut self, finished: usize, elapsed: Duration) -> Option<Line> {
        self.done = (self.done + finished).min(self.total);
        let tenth = (self.done * 10).checked_div(self.total).unwrap_or(10);
        let due = match self.last {
            _ if self.done == self.total => true,
            None => self.done >= FIRST_FEW.min(self.total),
            Some((at, last_tenth)) => {
                let gap = elapsed.saturating_sub(at);
                gap >= MAX_GAP || (gap >= MIN_GAP && tenth > last_tenth)
            }
        };
        if !due {
            return None;
        }
        self.last = Some((elapsed, tenth));
        let left = (self.done > 0 && self.done < self.total)
            .then(|| elapsed.mul_f64((self.total - self.done) as f64 / self.done as f64));
        Some(Line {
            done: self.done,
            total: self.total,
            elapsed,
            left,
        })
    }
}

impl Line {
    /// For the bar's message, which shows the count and the elapsed time itself.
    pub fn short(&self) -> String {
        match self.left {
            Some(left) => format!("about {} left", duration(left)),
            None => format!("{} candidates", self.total),
        }
    }
}

impl std::fmt::Display for Line {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let percent = (self.done * 100).checked_div(self.total).unwrap_or(100);
        write!(
            f,
            "{} of {} candidates ({percent} %) in {}",
            self.done,
            self.total,
            duration(self.elapsed)
        )?;
        if let Some(left) = self.left {
            write!(f, ", about {} left", duration(left))?;
        }
        Ok(())
    }
}

/// A duration as a person reads it: `0.4 s`, `42 s`, `3 min 20 s`, `2 h 05 min`.
pub fn duration(d: Duration) -> String {
    let seconds = d.as_secs_f64();
    if seconds < 10.0 {
        return format!("{seconds:.1} s");
    }
    let whole = seconds.round() as u64;
    match whole {
        0..60 => format!("{whole} s"),
        60..3600 => format!("{} min {:02} s", whole / 60, whole % 60),
        _ => format!("{} h {:02} min", whole / 3600, (whole % 3600) / 60),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(seconds: f64) -> Duration {
        Duration::from_secs_f64(seconds)
    }

    /// A long search at a steady 0.1 s per candidate (1,000 s): the first estimate after the first
    /// few, then a line every [`MAX_GAP`] and one at each tenth, the last at the end.
    #[test]
    fn a_long_search_reports_at_a_steady_pace_with_the_time_left() {
        let mut pacer = Pacer::new(10_000);
        let mut lines = Vec::new();
        for k in 1..=10_000 {
            if let Some(line) = pacer.advance(1, s(0.1 * k as f64)) {
                lines.push(line);
            }
        }
        // First line after FIRST_FEW: 8 done in 0.8 s, 9,992 left at the same rate: 999.2 s.
        assert_eq!(lines[0].done, FIRST_FEW);
        let left = lines[0].left.unwrap().as_secs_f64();
        assert!((left - 999.2).abs() < 1e-6, "{left}");
        // Lines at 0.8 s, 10.8 s, …, 90.8 s, then at each tenth (100 s, 200 s, …) and every 10 s
        // after it: 10 + 9·10 + the end.
        assert_eq!(lines.len(), 101);
        for w in lines.windows(2) {
            let gap = (w[1].elapsed - w[0].elapsed).as_secs_f64();
            assert!(
                (2.0..=10.0 + 1e-6).contains(&gap),
                "{gap} s between {:?} and {:?}",
                w[0],
                w[1]
            );
        }
        for tenth in 1..=10 {
            assert!(lines.iter().any(|l| l.done == tenth * 1_000), "no line at {tenth}/10");
        }
        let last = lines.last().unwrap();
        assert_eq!((last.done, last.total, last.left), (10_000, 10_000, None));
        // At half way after 500 s, 500 s left.
        let middle = lines.iter().find(|l| l.done == 5_000).unwrap();
        assert!((middle.left.unwrap().as_secs_f64() - 500.0).abs() < 1e-6);
        assert_eq!(
            middle.to_string(),
            "5000 of 10000 candidates (50 %) in 8 min 20 s, about 8 min 20 s left"
        );
    }

    /// A fast search: a line per tenth at most every [`MIN_GAP`], not one per candidate.
    #[test]
    fn a_fast_search_prints_a_line_per_tenth_at_most_every_two_seconds() {
        let mut pacer = Pacer::new(1_000);
        let times: Vec<f64> = (1..=1_000).map(|k| 0.025 * k as f64).collect();
        let lines: Vec<Line> = times.iter().filter_map(|&t| pacer.advance(1, s(t))).collect();
        // 25 s in all: the first estimate at 8 (0.2 s), then the tenths crossed at ≥ 2 s apart:
        // 100 at 2.5 s, 200 at 5 s, …, 900 at 22.5 s, and 1,000 at 25 s.
        let done: Vec<usize> = lines.iter().map(|l| l.done).collect();
        assert_eq!(done, [8, 100, 200, 300, 400, 500, 600, 700, 800, 900, 1_000]);
    }

    /// Bursts (a parallel worker finishing many at once) and a search smaller than the first few.
    #[test]
    fn a_small_search_still_prints_its_end_and_bursts_do_not_overflow() {
        let mut pacer = Pacer::new(3);
        assert_eq!(pacer.advance(2, s(0.1)), None);
        let last = pacer.advance(2, s(0.2)).unwrap();
        assert_eq!((last.done, last.total), (3, 3));
        assert_eq!(last.to_string(), "3 of 3 candidates (100 %) in 0.2 s");
    }

    #[test]
    fn durations_read_as_a_person_would_say_them() {
        assert_eq!(duration(s(0.44)), "0.4 s");
        assert_eq!(duration(s(42.4)), "42 s");
        assert_eq!(duration(s(200.0)), "3 min 20 s");
        assert_eq!(duration(s(2.0 * 3600.0 + 5.0 * 60.0 + 10.0)), "2 h 05 min");
    }
}
