//! The orientation of a six-dimensional Polyline (OpenSCENARIO 1.3 §6.9 "Trajectories": a
//! trajectory "may also be specified using the three-positional dimensions and the
//! three-rotational dimensions (heading, pitch and roll) … In the second case, the path not
//! only specifies the movement of the entity along the path, but also the orientation of the
//! corresponding entity during that movement").
//!
//! A Polyline is six-dimensional here when every `Vertex/Position` states its heading (an
//! `Orientation` element, or `h` on a WorldPosition). Between two vertices the heading turns
//! linearly in arc length, the shorter way round. The standard names the orientation at the
//! vertices only; linear interpolation is oscsim's convention, and esmini 3.6.0 interpolates
//! the same way when it follows such a polyline (pedestrian.xosc: the walker turns over the
//! short diagonal piece instead of snapping at its corners).

use opendrive::{normalize_angle, Real};

/// Headings (rad) at arc lengths (m, non-decreasing), at least two.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Orientations {
    s: Vec<Real>,
    h: Vec<Real>,
}

impl Orientations {
    /// Headings `h` at the vertices' arc lengths `s` (same length, at least two: checked by
    /// the caller).
    pub(crate) fn new(s: Vec<Real>, h: Vec<Real>) -> Self {
        debug_assert!(s.len() == h.len() && s.len() >= 2);
        Self { s, h }
    }

    /// The heading at arc length `s`, clamped to the first and last vertex; at coincident
    /// vertices (a turn on the spot) the later one's heading.
    pub(crate) fn at(&self, s: Real) -> Real {
        let last = self.s.len() - 1;
        if s <= self.s[0] {
            return self.h[0];
        }
        if s >= self.s[last] {
            return self.h[last];
        }
        let i = self.s.partition_point(|&v| v <= s).clamp(1, last);
        let (s0, s1) = (self.s[i - 1], self.s[i]);
        let f = if s1 > s0 { (s - s0) / (s1 - s0) } else { 1.0 };
        let turn = normalize_angle(self.h[i] - self.h[i - 1]);
        normalize_angle(self.h[i - 1] + f * turn)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn turns_linearly_the_shorter_way() {
        // 0 rad at 0 m, 3π/4 at 10 m, −3π/4 (= 5π/4) at 20 m: a quarter of the way along
        // the first piece is 3π/16; half-way along the second, across ±π, is π (the short
        // way is +π/2 over the piece, not −3π/2).
        let o = Orientations::new(vec![0.0, 10.0, 20.0], vec![0.0, 0.75 * PI, -0.75 * PI]);
        assert!((o.at(2.5) - 3.0 * PI / 16.0).abs() < 1e-12);
        assert!((normalize_angle(o.at(15.0) - PI)).abs() < 1e-12);
        assert!((o.at(-1.0)).abs() < 1e-12 && (o.at(25.0) + 0.75 * PI).abs() < 1e-12);
    }
}
