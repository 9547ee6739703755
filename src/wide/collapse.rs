//! Chapter 8's binary tree collapsed into nodes of `W` lanes (four, or
//! eight where the CPU has AVX2), and its leaves into packets.

use ch08_bvh::build;

use super::node::{Child, Node};
use super::packet::{self, Packet};
use super::primitive::Primitive;

/// Chapter 8's tree `binary` collapsed into nodes of `W` lanes (root
/// first), the leaves' primitives appended to `packets`.
pub(super) fn collapse<const W: usize>(
    binary: &[build::Node],
    primitives: &[Primitive],
    packets: &mut Vec<Packet>,
) -> Vec<Node<W>> {
    let mut nodes = Vec::with_capacity(binary.len() / (W / 2) + 1);
    if !binary.is_empty() {
        let mut tree = Collapse {
            spans: spans(binary),
            binary,
            primitives,
            nodes: &mut nodes,
            packets,
        };
        tree.node(0);
    }
    nodes
}

/// Chapter 8's binary tree, being collapsed into nodes of `W` lanes and
/// the leaves' packets.
struct Collapse<'t, const W: usize> {
    binary: &'t [build::Node],
    /// Each binary node's primitives: (first, count).
    spans: Vec<(u32, u32)>,
    /// In the order of the binary tree's leaves.
    primitives: &'t [Primitive],
    nodes: &'t mut Vec<Node<W>>,
    packets: &'t mut Vec<Packet>,
}

impl<const W: usize> Collapse<'_, W> {
    /// Appends the `W`-wide node standing for binary node `index` and the
    /// subtree below it; returns its index.
    ///
    /// Its lanes start as the binary node's two children. While a lane
    /// holds an inner node and a lane is free, the inner child with the
    /// largest box (the one rays most often enter) is replaced by its own
    /// two children. A binary leaf at the root becomes a node with one leaf
    /// lane.
    fn node(&mut self, index: usize) -> u32 {
        let binary = self.binary;
        let at = self.nodes.len();
        self.nodes.push(Node::EMPTY);
        let mut lanes = if self.is_leaf(index) {
            vec![index]
        } else {
            vec![index + 1, binary[index].start as usize]
        };
        while lanes.len() < W {
            let inner = lanes
                .iter()
                .enumerate()
                .filter(|&(_, &n)| !self.is_leaf(n))
                .max_by(|a, b| area(binary, *a.1).total_cmp(&area(binary, *b.1)));
            let Some((lane, &n)) = inner else { break };
            lanes.swap_remove(lane);
            lanes.extend([n + 1, binary[n].start as usize]);
        }
        for (lane, &n) in lanes.iter().enumerate() {
            let child = if self.is_leaf(n) {
                let (start, count) = self.spans[n];
                self.leaf(start, count)
            } else {
                Child::Node(self.node(n))
            };
            self.nodes[at].set(lane, binary[n].bounds, child);
        }
        at as u32
    }

    /// Is binary node `n` a leaf here: a leaf of chapter 8's tree, or a
    /// subtree of at most [`leaf_max`]`(W)` primitives?
    fn is_leaf(&self, n: usize) -> bool {
        let (_, count) = self.spans[n];
        self.binary[n].count > 0 || count <= leaf_max(W)
    }

    /// The packets of the binary leaf of `count` primitives from `start`.
    fn leaf(&mut self, start: u32, count: u32) -> Child {
        let first = self.packets.len();
        let (start, end) = (start as usize, (start + count) as usize);
        packet::pack(&self.primitives[start..end], self.packets);
        Child::Leaf {
            start: first as u32,
            count: (self.packets.len() - first) as u32,
        }
    }
}

/// In a tree of `w` lanes, a subtree of chapter 8's tree of at most this
/// many primitives becomes one leaf. Each fills one lane of a packet of
/// four of its kind: a sphere, a triangle or a cone (`cone.rs`).
///
/// Four wide: 8, two packets at most, if of one kind (why:
/// book/appendix/performance.md, "Profile and what it bought"). Eight
/// wide: 4, one packet, since a node's eight boxes cost one test, so a
/// ray can be told cheaply which of two packets it misses (8 to 13% fewer
/// instructions than with 8 on four of five SPD scenes: "Eight lanes").
const fn leaf_max(w: usize) -> u32 {
    if w >= 8 { 4 } else { 8 }
}

/// The primitives under each node of chapter 8's tree, (first, count): a
/// subtree's are contiguous, its first child's before its second's.
fn spans(binary: &[build::Node]) -> Vec<(u32, u32)> {
    let mut spans = vec![(0, 0); binary.len()];
    // Children come after their parent: work from the end.
    for n in (0..binary.len()).rev() {
        spans[n] = match binary[n] {
            build::Node {
                count: 0, start, ..
            } => {
                let ((first, left), (second, right)) = (spans[n + 1], spans[start as usize]);
                debug_assert_eq!(
                    first + left,
                    second,
                    "a subtree's primitives are contiguous"
                );
                (first, left + right)
            }
            build::Node { start, count, .. } => (start, count),
        };
    }
    spans
}

fn area(binary: &[build::Node], n: usize) -> f32 {
    binary[n].bounds.half_area()
}
