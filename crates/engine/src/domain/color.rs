//! OpenSCENARIO 2.0 §8.7.11 enum color and its RGB table.
//!
//! The seed says the set is "based on the set defined by W3C for HTML basic colors", but its
//! table gives fuchsia RGB(255,255,0) (which is yellow's value, two rows above) and purple
//! RGB(255,0,255) (which is W3C's fuchsia). oscsim follows the source the seed itself names,
//! the W3C HTML 4.01 basic colour keywords (also CSS Color Level 3 §4.1): fuchsia =
//! RGB(255,0,255) and purple = RGB(128,0,128). With the seed's values two colours would share
//! one RGB triple and `Color::from_rgb` could not invert `Color::rgb`; with W3C's all sixteen
//! are distinct.

/// §8.7.11 color: the colour of a physical_object, for debugging and visualisation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Color {
    /// RGB(255,255,255)
    White,
    /// RGB(192,192,192)
    Silver,
    /// RGB(128,128,128)
    Gray,
    /// RGB(0,0,0)
    Black,
    /// RGB(255,0,0)
    Red,
    /// RGB(128,0,0)
    Maroon,
    /// RGB(255,255,0)
    Yellow,
    /// RGB(128,128,0)
    Olive,
    /// RGB(0,255,0)
    Lime,
    /// RGB(0,128,0)
    Green,
    /// RGB(0,255,255)
    Aqua,
    /// RGB(0,128,128)
    Teal,
    /// RGB(0,0,255)
    Blue,
    /// RGB(0,0,128)
    Navy,
    /// RGB(255,0,255), W3C's value (the seed's table prints RGB(255,255,0), yellow's).
    Fuchsia,
    /// RGB(128,0,128), W3C's value (the seed's table prints RGB(255,0,255), fuchsia's).
    Purple,
}

/// The table of §8.7.11 in the seed's order, with the W3C values for fuchsia and purple.
const TABLE: [(Color, &str, [u8; 3]); 16] = [
    (Color::White, "white", [255, 255, 255]),
    (Color::Silver, "silver", [192, 192, 192]),
    (Color::Gray, "gray", [128, 128, 128]),
    (Color::Black, "black", [0, 0, 0]),
    (Color::Red, "red", [255, 0, 0]),
    (Color::Maroon, "maroon", [128, 0, 0]),
    (Color::Yellow, "yellow", [255, 255, 0]),
    (Color::Olive, "olive", [128, 128, 0]),
    (Color::Lime, "lime", [0, 255, 0]),
    (Color::Green, "green", [0, 128, 0]),
    (Color::Aqua, "aqua", [0, 255, 255]),
    (Color::Teal, "teal", [0, 128, 128]),
    (Color::Blue, "blue", [0, 0, 255]),
    (Color::Navy, "navy", [0, 0, 128]),
    (Color::Fuchsia, "fuchsia", [255, 0, 255]),
    (Color::Purple, "purple", [128, 0, 128]),
];

impl Color {
    /// All sixteen values in the order of the seed's table (§8.7.11).
    pub const ALL: [Color; 16] = {
        let mut all = [Color::White; 16];
        let mut i = 0;
        while i < 16 {
            all[i] = TABLE[i].0;
            i += 1;
        }
        all
    };

    /// The colour's RGB triple (§8.7.11, W3C values; see the module doc).
    pub fn rgb(self) -> [u8; 3] {
        TABLE[self as usize].2
    }

    /// The colour's name as §8.7.11 spells it, e.g. `"fuchsia"`.
    pub fn name(self) -> &'static str {
        TABLE[self as usize].1
    }

    /// The §8.7.11 colour named `name` (seed spelling, lower case), if there is one.
    pub fn from_name(name: &str) -> Option<Color> {
        TABLE
            .iter()
            .find(|(_, n, _)| *n == name)
            .map(|(c, _, _)| *c)
    }

    /// The §8.7.11 colour whose RGB triple is exactly `rgb`, if there is one.
    pub fn from_rgb(rgb: [u8; 3]) -> Option<Color> {
        TABLE.iter().find(|(_, _, v)| *v == rgb).map(|(c, _, _)| *c)
    }
}
