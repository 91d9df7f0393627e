//! erfc / normal CDF.

use super::*;

#[test]
#[allow(clippy::excessive_precision)] // reference digits kept as printed by mpmath
fn erfc_matches_high_precision_values() {
    // Reference: mpmath 1.4.1 with mp.dps = 40, `mpmath.erfc(mpmath.mpf(x))`, rounded to 20
    // significant digits. Covers every interval of Cody's approximation, both interval
    // breaks (0.46875 and 4), negative arguments and the far tail down to 1e-307.
    let table: [(f64, f64); 25] = [
        (-5.0, 1.9999999999984625402),
        (-2.5, 1.9995930479825550411),
        (-1.0, 1.8427007929497148693),
        (-0.3, 1.3286267594591274276),
        (0.0, 1.0),
        (1e-10, 9.9999999988716208329e-1),
        (0.1, 8.875370839817151078e-1),
        (0.46875, 5.0738652678206200841e-1),
        (0.47, 5.0625494911391786348e-1),
        (0.5, 4.7950012218695346232e-1),
        (1.0, 1.5729920705028513066e-1),
        (1.5, 3.3894853524689272933e-2),
        (2.0, 4.6777349810472658379e-3),
        (3.0, 2.2090496998585441373e-5),
        (3.99, 1.6739211364520843377e-8),
        (4.0, 1.5417257900280018852e-8),
        (4.01, 1.4196939421371026189e-8),
        (5.0, 1.5374597944280348502e-12),
        (6.0, 2.1519736712498913117e-17),
        (8.0, 1.122429717298292708e-29),
        (10.0, 2.088487583762544757e-45),
        (15.0, 7.2129941724512066666e-100),
        (20.0, 5.3958656116079009289e-176),
        (26.0, 5.6631924088561428465e-296),
        (26.5, 2.2109076642637342759e-307),
    ];
    for (x, expected) in table {
        assert_rel(erfc(x), expected, 1e-14, &format!("erfc({x})"));
    }
}

#[test]
fn erfc_edge_cases() {
    assert_eq!(erfc(30.0), 0.0);
    assert_eq!(erfc(f64::INFINITY), 0.0);
    assert_eq!(erfc(-30.0), 2.0);
    assert_eq!(erfc(f64::NEG_INFINITY), 2.0);
    assert!(erfc(f64::NAN).is_nan());
    assert_eq!(normal_cdf(0.0), 0.5);
}

#[test]
#[allow(clippy::excessive_precision)] // reference digits kept as printed by mpmath
fn normal_cdf_known_values() {
    // Values given in the brief, and mpmath 1.4.1 (`mpmath.ncdf`, mp.dps = 40) for the rest.
    assert_rel(normal_cdf(1.96), 0.9750021048517795, 1e-12, "Phi(1.96)");
    assert_rel(erfc(3.0), 2.209049699858544e-05, 1e-12, "erfc(3)");
    assert_rel(normal_cdf(-1.96), 0.024997895148220434137, 1e-12, "Phi(-1.96)");
    assert_rel(normal_cdf(0.5), 0.69146246127401310364, 1e-12, "Phi(0.5)");
    // Lower tail keeps relative precision where 1 - Phi(8) would be 0 in f64.
    assert_rel(normal_cdf(-8.0), 6.2209605742717841235e-16, 1e-12, "Phi(-8)");
}
