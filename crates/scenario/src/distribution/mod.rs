//! OpenSCENARIO 1.3 §9.5 parameter value distributions (deterministic and stochastic).
