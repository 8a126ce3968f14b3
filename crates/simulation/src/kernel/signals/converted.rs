//! Converted signals ([`SignalKind::Converted`]): the port of mode `in` associated with
//! `to_bit(s)`, the actual of `to_bool(y) => yb`. Each takes the conversion of its source's
//! value in every cycle in which the source is active (LRM 12.6.2: the conversion is part of
//! the effective value, so no delta cycle passes between the two), and at initialisation.

use vams_design::{Design, SignalId, SignalKind, Value};

use super::super::error::SimError;
use super::Signals;

/// `(signal, source)` of every converted signal of `design`, in increasing order.
pub(super) fn of(design: &Design) -> Vec<(SignalId, SignalId)> {
    design
        .signals
        .iter()
        .enumerate()
        .filter_map(|(k, s)| match &s.kind {
            SignalKind::Converted { source, .. } => Some((SignalId(k as u32), *source)),
            _ => None,
        })
        .collect()
}

impl Signals {
    /// The initial values of the converted signals (after their sources' and the views'),
    /// then of the views of converted signals.
    pub(super) fn initialize_converted(&mut self, design: &Design) -> Result<(), SimError> {
        for k in 0..self.converted.len() {
            let (s, _) = self.converted[k];
            let value = self.convert(s, design, 0.0)?;
            let st = &mut self.states[s.index()];
            st.last_value = value.clone();
            st.value = value;
        }
        for k in 0..self.views_of_converted.len() {
            let v = self.views_of_converted[k];
            if let Some((parent, first, len)) = self.view_of[v.index()]
                && let Some(value) = self.states[parent.index()].value.view(first, len)
            {
                let st = &mut self.states[v.index()];
                st.last_value = value.clone();
                st.value = value;
            }
        }
        Ok(())
    }

    /// In the update phase, after the driven signals, views and gathers: each converted
    /// signal whose source is active becomes active with the conversion of the source's new
    /// value (an event when it differs), then the views of converted signals follow them.
    pub(super) fn update_converted(&mut self, now: f64, design: &Design) -> Result<(), SimError> {
        for k in 0..self.converted.len() {
            let (s, source) = self.converted[k];
            if !self.states[source.index()].active {
                continue;
            }
            let value = self.convert(s, design, now)?;
            self.activate(s, now);
            self.set(s, value, now);
        }
        for k in 0..self.views_of_converted.len() {
            self.follow_view(self.views_of_converted[k], now);
        }
        Ok(())
    }

    /// The conversion of converted signal `s`'s source, evaluated on the current values.
    fn convert(&self, s: SignalId, design: &Design, now: f64) -> Result<Value, SimError> {
        let signal = &design.signals[s.index()];
        let SignalKind::Converted { conversion, .. } = &signal.kind else {
            // `converted` lists the signals of this kind only.
            return Ok(self.states[s.index()].value.clone());
        };
        // A conversion function's objects live for its call only.
        let io = super::super::io::Io::default();
        let env = self.update_env(design, now, &io);
        let value: Result<Value, _> = super::super::eval::eval(conversion, &env);
        value.map_err(|e| SimError::Runtime {
            process: format!("conversion of `{}`", signal.name),
            time: now,
            message: e.message,
            span: signal.span,
            help: e.help.to_string(),
        })
    }
}
