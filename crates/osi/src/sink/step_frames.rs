//! [`StepFrames`]: the GroundTruths of each engine step, encoded, for the Python and C
//! bindings (the mapping is [`GroundTruthSink`]'s, ASAM OSI 3.8 osi_groundtruth.proto).

use engine::output::Frame;
use engine::SinkError;

use super::GroundTruthSink;

/// The GroundTruths of the frames of the latest step, encoded (osi_groundtruth.proto bytes):
/// the engine frame sink of the Python and C bindings, which hand them out between steps. The
/// first step has two frames (t = 0, with the lanes, and t = dt), later steps one, a call
/// after the run's end none; [`StepFrames::begin_step`] before each step forgets the last
/// step's frames, [`StepFrames::latest`] keeps the newest frame of the run.
pub struct StepFrames {
    sink: GroundTruthSink,
    frames: Vec<Vec<u8>>,
    latest: Vec<u8>,
}

impl StepFrames {
    /// No frames yet.
    pub fn new(sink: GroundTruthSink) -> Self {
        StepFrames {
            sink,
            frames: Vec::new(),
            latest: Vec::new(),
        }
    }

    /// Forgets the frames of the step before (call before each step).
    pub fn begin_step(&mut self) {
        if let Some(last) = self.frames.pop() {
            self.latest = last;
        }
        self.frames.clear();
    }

    /// The frames of the latest step, in time order.
    pub fn frames(&self) -> &[Vec<u8>] {
        &self.frames
    }

    /// The newest frame of the run (the current state), empty before the first step.
    pub fn latest(&self) -> &[u8] {
        self.frames.last().unwrap_or(&self.latest)
    }
}

impl engine::FrameSink for StepFrames {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), SinkError> {
        use prost::Message;
        let gt = self.sink.ground_truth(frame).map_err(SinkError::sink)?;
        self.frames.push(gt.encode_to_vec());
        Ok(())
    }
}
