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
    /// Encoding buffers; the first `count` hold this step's frames, the rest are kept for
    /// reuse (a step writes into last step's buffers: no allocation per frame once warm).
    frames: Vec<Vec<u8>>,
    count: usize,
    latest: Vec<u8>,
}

impl StepFrames {
    /// No frames yet.
    pub fn new(sink: GroundTruthSink) -> Self {
        StepFrames {
            sink,
            frames: Vec::new(),
            count: 0,
            latest: Vec::new(),
        }
    }

    /// Forgets the frames of the step before (call before each step).
    pub fn begin_step(&mut self) {
        if let Some(last) = self.count.checked_sub(1) {
            // The newest frame becomes `latest`; the old `latest` a spare buffer.
            std::mem::swap(&mut self.latest, &mut self.frames[last]);
        }
        self.count = 0;
    }

    /// The frames of the latest step, in time order.
    pub fn frames(&self) -> &[Vec<u8>] {
        &self.frames[..self.count]
    }

    /// The newest frame of the run (the current state), empty before the first step.
    pub fn latest(&self) -> &[u8] {
        self.frames().last().unwrap_or(&self.latest)
    }
}

impl engine::FrameSink for StepFrames {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), SinkError> {
        use prost::Message;
        let gt = self.sink.ground_truth(frame).map_err(SinkError::sink)?;
        if self.count == self.frames.len() {
            self.frames.push(Vec::new());
        }
        let buf = &mut self.frames[self.count];
        buf.clear();
        // Encoding into a Vec cannot run out of space: Vec grows as needed.
        gt.encode(buf).expect("encoding into a Vec<u8> never fails");
        self.count += 1;
        Ok(())
    }
}
