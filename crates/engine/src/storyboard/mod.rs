//! OpenSCENARIO 1.3 storyboard state machine: elements, states, transitions and triggers.
