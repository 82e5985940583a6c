//! OpenSCENARIO 2.0 §8.7 physical-object actors and their measurement methods.
