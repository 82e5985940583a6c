//! From OpenSCENARIO 1.2+ `Color` (attribute `colorType`, optional `ColorRgb` or
//! `ColorCmyk`, all channels 0..1) to ASAM OSI 3.8 `ColorDescription`.
//!
//! An explicit `ColorRgb` becomes `rgb`; a `ColorCmyk` becomes `cmyk` and also `rgb` by
//! the usual device conversion R = (1 − C)(1 − K), G = (1 − M)(1 − K), B = (1 − Y)(1 − K).
//! A bare `colorType` becomes the `rgb` of a plain sRGB colour chosen by oscsim (pure
//! primaries, mid grey 0.5, brown (0.6, 0.3, 0.0), violet (0.5, 0.0, 1.0), orange
//! (1.0, 0.5, 0.0)); `other` gives no colour.

use crate::error::Error;
use crate::osi3::{ColorCmyk, ColorDescription, ColorRgb};

const COLOR_TYPES: &str = "one of other, red, yellow, green, blue, violet, orange, brown, \
     black, grey, white";

/// `ColorDescription` with `rgb` from channels in 0..1.
pub fn from_rgb(red: f64, green: f64, blue: f64) -> Result<ColorDescription, Error> {
    for v in [red, green, blue] {
        check_unit(v)?;
    }
    Ok(ColorDescription {
        rgb: Some(ColorRgb {
            red: Some(red),
            green: Some(green),
            blue: Some(blue),
        }),
        ..Default::default()
    })
}

/// `ColorDescription` with `cmyk` and the derived `rgb` from channels in 0..1.
pub fn from_cmyk(
    cyan: f64,
    magenta: f64,
    yellow: f64,
    key: f64,
) -> Result<ColorDescription, Error> {
    for v in [cyan, magenta, yellow, key] {
        check_unit(v)?;
    }
    let mut color = from_rgb(
        (1.0 - cyan) * (1.0 - key),
        (1.0 - magenta) * (1.0 - key),
        (1.0 - yellow) * (1.0 - key),
    )?;
    color.cmyk = Some(ColorCmyk {
        cyan: Some(cyan),
        magenta: Some(magenta),
        yellow: Some(yellow),
        key: Some(key),
    });
    Ok(color)
}

/// `ColorDescription` of a bare OpenSCENARIO `colorType`; `None` for `other`.
pub fn from_color_type(color_type: &str) -> Result<Option<ColorDescription>, Error> {
    let rgb = match color_type {
        "other" => return Ok(None),
        "red" => (1.0, 0.0, 0.0),
        "yellow" => (1.0, 1.0, 0.0),
        "green" => (0.0, 1.0, 0.0),
        "blue" => (0.0, 0.0, 1.0),
        "violet" => (0.5, 0.0, 1.0),
        "orange" => (1.0, 0.5, 0.0),
        "brown" => (0.6, 0.3, 0.0),
        "black" => (0.0, 0.0, 0.0),
        "grey" => (0.5, 0.5, 0.5),
        "white" => (1.0, 1.0, 1.0),
        other => return Err(Error::invalid("colorType", COLOR_TYPES, other)),
    };
    from_rgb(rgb.0, rgb.1, rgb.2).map(Some)
}

fn check_unit(v: f64) -> Result<(), Error> {
    if (0.0..=1.0).contains(&v) {
        Ok(())
    } else {
        Err(Error::invalid(
            "a colour channel",
            "a number in 0..1",
            &v.to_string(),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn cmyk_converts_to_rgb() {
        // C=0.2, M=0.4, Y=0.6, K=0.5: R=(0.8)(0.5)=0.4, G=(0.6)(0.5)=0.3, B=(0.4)(0.5)=0.2.
        let c = from_cmyk(0.2, 0.4, 0.6, 0.5).unwrap();
        let rgb = c.rgb.unwrap();
        assert_relative_eq!(rgb.red.unwrap(), 0.4, epsilon = 1e-12);
        assert_relative_eq!(rgb.green.unwrap(), 0.3, epsilon = 1e-12);
        assert_relative_eq!(rgb.blue.unwrap(), 0.2, epsilon = 1e-12);
        assert_eq!(c.cmyk.unwrap().key, Some(0.5));
    }

    #[test]
    fn out_of_range_and_unknown_names_are_errors() {
        assert!(from_rgb(1.2, 0.0, 0.0).is_err());
        assert!(from_rgb(f64::NAN, 0.0, 0.0).is_err());
        assert!(from_color_type("pink").is_err());
        assert_eq!(from_color_type("other").unwrap(), None);
        let red = from_color_type("red").unwrap().unwrap().rgb.unwrap();
        assert_eq!(
            (red.red, red.green, red.blue),
            (Some(1.0), Some(0.0), Some(0.0))
        );
    }
}
