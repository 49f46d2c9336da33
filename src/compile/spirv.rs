//! Corrections to the SPIR-V naga (30) writes, where naga's output breaks a rule that
//! `spirv-val` checks; nothing else in the module changes:
//!
//! - the `SampleMask` built-in, which naga declares as a scalar `u32` while Vulkan requires an
//!   array of 32-bit integers (VUID-SampleMask-SampleMask-04359): the variable becomes an array
//!   of one, and each load and store reaches its element through an access chain;
//! - the size of a storage texture (`textureDimensions`, `textureNumLayers`), which naga queries
//!   with `OpImageQuerySizeLod`, allowed only on sampled images (VUID-StandaloneSpirv-
//!   OpImageQuerySizeLod-04659): it becomes `OpImageQuerySize`, which has no level;
//! - a read of a storage texture whose format SPIR-V cannot name (`bgra8unorm`), which needs the
//!   `StorageImageReadWithoutFormat` capability naga does not declare.

const OP_CAPABILITY: u32 = 17;
const OP_TYPE_IMAGE: u32 = 25;
const OP_IMAGE_READ: u32 = 98;
const OP_IMAGE_QUERY_SIZE_LOD: u32 = 103;
const OP_IMAGE_QUERY_SIZE: u32 = 104;
const CAPABILITY_STORAGE_IMAGE_READ_WITHOUT_FORMAT: u32 = 55;
const OP_TYPE_INT: u32 = 21;
const OP_TYPE_ARRAY: u32 = 28;
const OP_TYPE_POINTER: u32 = 32;
const OP_CONSTANT: u32 = 43;
const OP_VARIABLE: u32 = 59;
const OP_LOAD: u32 = 61;
const OP_STORE: u32 = 62;
const OP_ACCESS_CHAIN: u32 = 65;
const OP_DECORATE: u32 = 71;
const DECORATION_BUILT_IN: u32 = 11;
const BUILT_IN_SAMPLE_MASK: u32 = 20;

/// One instruction: its opcode and operand words.
struct Instruction {
    opcode: u32,
    operands: Vec<u32>,
}

impl Instruction {
    fn new(opcode: u32, operands: Vec<u32>) -> Instruction {
        Instruction { opcode, operands }
    }
}

/// A module's words as the bytes of its file (little-endian), copied a word at a time.
pub(super) fn to_bytes(words: &[u32]) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(words.len() * 4);
    for word in words {
        bytes.extend_from_slice(&word.to_le_bytes());
    }
    bytes
}

/// `words` with each correction made. A module that does not parse as SPIR-V, or needs none,
/// is returned as it is.
pub(super) fn corrected(words: Vec<u32>) -> Vec<u32> {
    // Most modules need none: found without building the instruction list.
    if !needs_correction(&words) {
        return words;
    }
    let Some(mut instructions) = parse(&words) else { return words };
    let mut bound = words[3];
    sample_mask_as_array(&mut instructions, &mut bound);
    storage_image_queries(&mut instructions);
    let mut out = Vec::with_capacity(words.len() + 32);
    out.extend_from_slice(&words[..5]);
    out[3] = bound;
    for instruction in instructions {
        out.push(((instruction.operands.len() as u32 + 1) << 16) | instruction.opcode);
        out.extend(instruction.operands);
    }
    out
}

/// Each size query of a storage image (`Sampled` 2) made `OpImageQuerySize`, and the capability
/// a read of one with an unknown format needs declared. An image operand is a loaded value, so
/// each is traced to its type through its `OpLoad`.
fn storage_image_queries(instructions: &mut Vec<Instruction>) {
    let storage_types: Vec<(u32, bool)> = instructions
        .iter()
        .filter(|i| i.opcode == OP_TYPE_IMAGE && i.operands.get(6) == Some(&2))
        .map(|i| (i.operands[0], i.operands.get(7) == Some(&0)))
        .collect();
    if storage_types.is_empty() {
        return;
    }
    // Every value's type: an image operand is a loaded value.
    let value_type: std::collections::HashMap<u32, u32> = instructions
        .iter()
        .filter(|i| i.opcode == OP_LOAD)
        .filter_map(|i| Some((*i.operands.get(1)?, *i.operands.first()?)))
        .collect();
    let storage = |image: u32| {
        let ty = value_type.get(&image)?;
        storage_types.iter().find(|(t, _)| t == ty).map(|(_, unknown_format)| *unknown_format)
    };
    let mut reads_unknown_format = false;
    for instruction in instructions.iter_mut() {
        let Some(&image) = instruction.operands.get(2) else { continue };
        match instruction.opcode {
            OP_IMAGE_QUERY_SIZE_LOD if storage(image).is_some() => {
                instruction.opcode = OP_IMAGE_QUERY_SIZE;
                instruction.operands.truncate(3);
            }
            OP_IMAGE_READ if storage(image) == Some(true) => reads_unknown_format = true,
            _ => {}
        }
    }
    let declared = instructions
        .iter()
        .any(|i| i.opcode == OP_CAPABILITY && i.operands == [CAPABILITY_STORAGE_IMAGE_READ_WITHOUT_FORMAT]);
    if reads_unknown_format && !declared {
        instructions
            .insert(0, Instruction::new(OP_CAPABILITY, vec![CAPABILITY_STORAGE_IMAGE_READ_WITHOUT_FORMAT]));
    }
}

/// Every scalar `SampleMask` variable made an array of one.
fn sample_mask_as_array(instructions: &mut Vec<Instruction>, bound: &mut u32) {
    let masks: Vec<u32> = instructions
        .iter()
        .filter(|i| {
            i.opcode == OP_DECORATE
                && i.operands.get(1..3) == Some(&[DECORATION_BUILT_IN, BUILT_IN_SAMPLE_MASK])
        })
        .map(|i| i.operands[0])
        .collect();
    let mut fresh = || {
        *bound += 1;
        *bound - 1
    };
    for mask in masks {
        let Some(at) =
            instructions.iter().position(|i| i.opcode == OP_VARIABLE && i.operands.get(1) == Some(&mask))
        else {
            continue;
        };
        let pointer = instructions[at].operands[0];
        let Some((class, element)) = instructions
            .iter()
            .find(|i| i.opcode == OP_TYPE_POINTER && i.operands[0] == pointer)
            .map(|i| (i.operands[1], i.operands[2]))
        else {
            continue;
        };
        // Only a scalar 32-bit integer needs it: an array (from another writer) is left alone.
        if !instructions.iter().any(|i| i.opcode == OP_TYPE_INT && i.operands.first() == Some(&element)) {
            continue;
        }
        let unsigned = instructions
            .iter()
            .find(|i| i.opcode == OP_TYPE_INT && i.operands.get(1..3) == Some(&[32, 0]))
            .map(|i| i.operands[0]);
        let (zero, one, array, array_pointer) = (fresh(), fresh(), fresh(), fresh());
        let mut declarations = Vec::new();
        let index_type = match unsigned {
            Some(id) => id,
            None => {
                let id = fresh();
                declarations.push(Instruction::new(OP_TYPE_INT, vec![id, 32, 0]));
                id
            }
        };
        declarations.push(Instruction::new(OP_CONSTANT, vec![index_type, zero, 0]));
        declarations.push(Instruction::new(OP_CONSTANT, vec![index_type, one, 1]));
        declarations.push(Instruction::new(OP_TYPE_ARRAY, vec![array, element, one]));
        declarations.push(Instruction::new(OP_TYPE_POINTER, vec![array_pointer, class, array]));
        instructions[at].operands[0] = array_pointer;
        instructions.splice(at..at, declarations);
        // Each load and store of the variable goes through its one element.
        let mut i = 0;
        while i < instructions.len() {
            let operand = match instructions[i].opcode {
                OP_LOAD => 2,
                OP_STORE => 0,
                _ => {
                    i += 1;
                    continue;
                }
            };
            if instructions[i].operands.get(operand) != Some(&mask) {
                i += 1;
                continue;
            }
            let chain = fresh();
            instructions[i].operands[operand] = chain;
            instructions.insert(i, Instruction::new(OP_ACCESS_CHAIN, vec![pointer, chain, mask, zero]));
            i += 2;
        }
    }
}

/// Whether any instruction is one a correction is for: `OpDecorate %x BuiltIn SampleMask`, a
/// size query with a level, or an image read.
fn needs_correction(words: &[u32]) -> bool {
    let mut at = 5;
    while at < words.len() {
        let count = (words[at] >> 16) as usize;
        if count == 0 {
            return false;
        }
        let opcode = words[at] & 0xffff;
        if opcode == OP_IMAGE_QUERY_SIZE_LOD
            || opcode == OP_IMAGE_READ
            || opcode == OP_DECORATE
                && words.get(at + 2..at + 4) == Some(&[DECORATION_BUILT_IN, BUILT_IN_SAMPLE_MASK])
        {
            return true;
        }
        at += count;
    }
    false
}

fn parse(words: &[u32]) -> Option<Vec<Instruction>> {
    if words.len() < 5 || words[0] != 0x0723_0203 {
        return None;
    }
    let mut instructions = Vec::new();
    let mut at = 5;
    while at < words.len() {
        let count = (words[at] >> 16) as usize;
        if count == 0 || at + count > words.len() {
            return None;
        }
        instructions.push(Instruction::new(words[at] & 0xffff, words[at + 1..at + count].to_vec()));
        at += count;
    }
    Some(instructions)
}
