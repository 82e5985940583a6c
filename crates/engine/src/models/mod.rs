//! The driver and vehicle models behind the built-in controllers (OpenSCENARIO 1.3 §6.6
//! "Controllers": user-defined controllers with their own interpretation of the control
//! strategies): pure functions of the quantities each model reads, each with its source.
//!
//! | module | model |
//! | --- | --- |
//! | `idm` | Intelligent Driver Model (Treiber, Hennecke, Helbing 2000), ballistic integration |
//! | `fourth_power` | the IDM's (v/v0)^δ at δ = 4 with the bits of libm's `pow`, mostly without calling it |
//! | `mobil` | MOBIL lane-change decision (Kesting, Treiber, Helbing 2007) |
//! | `acc` | adaptive cruise control, constant time gap, ISO 15622 limits |
//! | `single_track` | pedals, gear and steering wheel → motion: kinematic single-track model |

pub mod acc;
mod fourth_power;
pub mod idm;
pub mod mobil;
pub mod single_track;
