//! A minimal writer of classic (CDF-1) NetCDF headers, for tests that need crafted files: a
//! forecast whose header declares far more data than the file holds.

/// A classic (CDF-1) NetCDF header with `time`, `lat`, `lon` coordinates (their values
/// written) and `uo`, `vo` (time, lat, lon) whose data lie beyond the end of the file: a
/// forecast that declares far more than it holds.
pub fn forecast_bomb(steps: u32, nlat: u32, nlon: u32) -> Vec<u8> {
    fn name(out: &mut Vec<u8>, s: &str) {
        out.extend((s.len() as u32).to_be_bytes());
        out.extend(s.as_bytes());
        out.resize(out.len().div_ceil(4) * 4, 0);
    }
    fn text_attr(out: &mut Vec<u8>, key: &str, value: &str) {
        name(out, key);
        out.extend(2u32.to_be_bytes()); // NC_CHAR
        name(out, value);
    }
    const DIM: u32 = 0x0A;
    const VAR: u32 = 0x0B;
    const ATT: u32 = 0x0C;
    const DOUBLE: u32 = 6;
    const FLOAT: u32 = 5;
    let dims = [("time", steps), ("lat", nlat), ("lon", nlon)];
    // (name, dim ids, units, type, element size)
    let vars: [(&str, Vec<u32>, &str, u32, u32); 5] = [
        ("time", vec![0], "hours since 2025-01-01 00:00:00", DOUBLE, 8),
        ("lat", vec![1], "degrees_north", DOUBLE, 8),
        ("lon", vec![2], "degrees_east", DOUBLE, 8),
        ("uo", vec![0, 1, 2], "m s-1", FLOAT, 4),
        ("vo", vec![0, 1, 2], "m s-1", FLOAT, 4),
    ];
    let build = |begins: &[u32]| -> Vec<u8> {
        let mut h = b"CDF\x01".to_vec();
        h.extend(0u32.to_be_bytes());
        h.extend(DIM.to_be_bytes());
        h.extend((dims.len() as u32).to_be_bytes());
        for (n, len) in dims {
            name(&mut h, n);
            h.extend(len.to_be_bytes());
        }
        h.extend([0u8; 8]); // no global attributes
        h.extend(VAR.to_be_bytes());
        h.extend((vars.len() as u32).to_be_bytes());
        for (k, (n, ids, units, ty, size)) in vars.iter().enumerate() {
            name(&mut h, n);
            h.extend((ids.len() as u32).to_be_bytes());
            for id in ids {
                h.extend(id.to_be_bytes());
            }
            h.extend(ATT.to_be_bytes());
            h.extend(1u32.to_be_bytes());
            text_attr(&mut h, "units", units);
            h.extend(ty.to_be_bytes());
            let count: u64 = ids.iter().map(|&i| u64::from(dims[i as usize].1)).product();
            let vsize = (count * u64::from(*size)).min(u64::from(u32::MAX - 3)) as u32;
            h.extend(vsize.div_ceil(4).saturating_mul(4).to_be_bytes());
            h.extend(begins[k].to_be_bytes());
        }
        h
    };
    let header_len = build(&[0; 5]).len() as u32;
    let mut begins = [0u32; 5];
    let mut at = header_len;
    for (k, (_, ids, _, _, size)) in vars.iter().enumerate() {
        begins[k] = at;
        let count: u64 = ids.iter().map(|&i| u64::from(dims[i as usize].1)).product();
        at = at.saturating_add((count * u64::from(*size)).min(u64::from(u32::MAX / 2)) as u32);
    }
    let mut file = build(&begins);
    for k in 0..steps {
        file.extend(f64::from(k).to_be_bytes());
    }
    for j in 0..nlat {
        file.extend((48.0 + f64::from(j) / f64::from(nlat - 1)).to_be_bytes());
    }
    for i in 0..nlon {
        file.extend((-125.0 + f64::from(i) / f64::from(nlon - 1)).to_be_bytes());
    }
    file
}
