//! The timeouts of the waiting processes, earliest first: a binary heap with its earliest
//! entry kept outside it.
//!
//! A process waiting with a timeout (`wait for 1 ns`) that resumes from it and waits again
//! takes its entry off and puts a new one on, at every activation. With the earliest entry in
//! a slot of its own, the usual cases, one or few processes waiting with a timeout, or the new
//! timeout being the earliest, cost a comparison and a copy instead of the heap's pop and push
//! with their sifts; the heap holds the later ones.

use std::cmp::{Ordering, Reverse};
use std::collections::BinaryHeap;

/// A process's timeout: its time and the process, ordered by time then process.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Due(pub f64, pub usize);

impl PartialEq for Due {
    fn eq(&self, other: &Due) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Due {}

impl PartialOrd for Due {
    fn partial_cmp(&self, other: &Due) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Due {
    fn cmp(&self, other: &Due) -> Ordering {
        self.0.total_cmp(&other.0).then(self.1.cmp(&other.1))
    }
}

/// A priority queue of [`Due`] entries, earliest first (the order of a `BinaryHeap` of
/// `Reverse<Due>`: time, then process).
#[derive(Debug, Default)]
pub(crate) struct Timeouts {
    /// The earliest entry; `None` only when `later` is empty too.
    first: Option<Due>,
    /// The other entries.
    later: BinaryHeap<Reverse<Due>>,
}

impl Timeouts {
    /// The earliest entry.
    #[inline]
    pub fn peek(&self) -> Option<Due> {
        self.first
    }

    /// Takes the earliest entry off.
    #[inline]
    pub fn pop(&mut self) {
        self.first = None;
        if !self.later.is_empty() {
            self.first_from_later();
        }
    }

    /// The heap's earliest entry moved into the slot: out of line, so that the callers in
    /// the kernel's loop stay small enough to be inlined (with the heap's pop inlined,
    /// `EventKernel::next_time` was not, and its call cost more than the pop saved).
    #[inline(never)]
    fn first_from_later(&mut self) {
        self.first = self.later.pop().map(|Reverse(d)| d);
    }

    /// Adds `due`.
    #[inline]
    pub fn push(&mut self, due: Due) {
        match self.first {
            None => self.first = Some(due),
            Some(first) => self.push_later(first, due),
        }
    }

    /// [`Timeouts::push`] beside an earliest entry `first`: out of line, as
    /// [`Timeouts::first_from_later`].
    #[inline(never)]
    fn push_later(&mut self, first: Due, due: Due) {
        if due < first {
            self.later.push(Reverse(first));
            self.first = Some(due);
        } else {
            self.later.push(Reverse(due));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The entries come off in the order of a binary heap of the same entries, whatever the
    /// interleaving of pushes and pops.
    #[test]
    fn timeouts_come_off_in_heap_order() {
        let mut seed = 12345u64;
        let mut next = move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed >> 33
        };
        let mut queue = Timeouts::default();
        let mut heap = BinaryHeap::new();
        for _ in 0..20_000 {
            if next() % 3 == 0 {
                assert_eq!(
                    queue.peek(),
                    heap.peek().map(|Reverse(d): &Reverse<Due>| *d)
                );
                queue.pop();
                heap.pop();
            } else {
                // Few distinct times, so that ties are ordered by the process.
                let due = Due((next() % 16) as f64 * 1e-9, (next() % 8) as usize);
                queue.push(due);
                heap.push(Reverse(due));
            }
            assert_eq!(queue.peek(), heap.peek().map(|Reverse(d)| *d));
        }
        while heap.pop().is_some() {
            queue.pop();
            assert_eq!(queue.peek(), heap.peek().map(|Reverse(d)| *d));
        }
        assert_eq!(queue.peek(), None);
    }
}
