//! Textbook cases.

use super::*;
use crate::stats::rank_sum::normal_p_two_sided;

#[test]
fn textbook_hollander_wolfe_permeability_exact() {
    // Hollander & Wolfe (1973), p. 69 f., the two-sample example of R's ?wilcox.test:
    // permeability constants of the human chorioamnion at term (x) and at 12-26 weeks (y).
    // Published (R documentation example, alternative = "greater"): W = 35,
    // p-value = 0.1272, so the two-sided value is 0.2544 (the exact distribution is
    // symmetric).
    let x = [0.80, 0.83, 1.89, 1.04, 1.45, 1.38, 1.91, 1.64, 0.73, 1.46];
    let y = [1.15, 0.88, 0.90, 0.74, 1.21];
    let r = rank_sum_test(&x, &y);
    assert_eq!(r.method, Method::Exact);
    assert_eq!(r.z, None);
    assert_eq!(r.u_x, 35.0);
    assert_abs(r.p_value, 0.2544, 0.5e-4, "published two-sided p (4 d.p.)");
    assert_abs(r.p_value / 2.0, 0.1272, 0.5e-4, "published one-sided p (4 d.p.)");
    // scipy 1.17.1: scipy.stats.mannwhitneyu(x, y, alternative='two-sided',
    // method='exact') -> statistic 35.0, pvalue 0.2544122544122544 (= 764/3003).
    assert_rel(r.p_value, 0.2544122544122544, 1e-6, "scipy exact (relative)");
    assert_rel(r.p_value, 764.0 / 3003.0, 1e-14, "exact fraction");
}

#[test]
fn textbook_shier_diabetes_ages_exact() {
    // R. Shier, "Statistics: 2.3 The Mann-Whitney U Test", Mathematics Learning Support
    // Centre (2004), as reproduced in the scipy.stats.mannwhitneyu documentation example:
    // age at diagnosis of type II diabetes. Published: U_M = 17, U_F = 3, p = 0.11.
    let males = [19.0, 22.0, 16.0, 29.0, 24.0];
    let females = [20.0, 11.0, 17.0, 12.0];
    let r = rank_sum_test(&males, &females);
    assert_eq!(r.method, Method::Exact);
    assert_eq!(r.u_x, 17.0);
    assert_eq!(rank_sum_test(&females, &males).u_x, 3.0);
    assert_abs(r.p_value, 0.11, 0.005, "published p (2 d.p.)");
    // scipy 1.17.1: mannwhitneyu(males, females, alternative='two-sided',
    // method='exact') -> 0.1111111111111111 (printed in the scipy docs too).
    assert_rel(r.p_value, 0.1111111111111111, 1e-6, "scipy exact (relative)");
    // The docs' asymptotic value for the same data, checking the normal branch on data
    // without ties: mannwhitneyu(males, females, method='asymptotic') (use_continuity=True)
    // -> 0.11134688653314041.
    let (z, p) = normal_p_two_sided(17.0, 5, 4, 0.0, 9);
    assert_rel(p, 0.11134688653314041, 1e-6, "scipy docs asymptotic (relative)");
    assert!(z.unwrap() > 0.0);
}

#[test]
fn textbook_wikipedia_tortoise_hare_u() {
    // Wikipedia, "Mann-Whitney U test", section "Illustration of calculation methods":
    // finishing order T H H H H H T T T T T H, the first animal home gets rank 12.
    // Published: U_T = 11 (tortoise rank sum 32 - 21), U_H = 25, U_T + U_H = 36.
    let tortoises = [12.0, 6.0, 5.0, 4.0, 3.0, 2.0];
    let hares = [11.0, 10.0, 9.0, 8.0, 7.0, 1.0];
    let rt = rank_sum_test(&tortoises, &hares);
    let rh = rank_sum_test(&hares, &tortoises);
    assert_eq!(rt.u_x, 11.0);
    assert_eq!(rh.u_x, 25.0);
    assert_eq!(rt.method, Method::Exact);
    // Wikipedia: not significant (critical value 5 for 6 vs 6 at 0.05, two-tailed).
    // scipy 1.17.1: mannwhitneyu(tortoises, hares, alternative='two-sided',
    // method='exact') -> 0.30952380952380953 (= 13/42).
    assert_rel(rt.p_value, 0.30952380952380953, 1e-6, "scipy exact (relative)");
    assert_eq!(rt.p_value, rh.p_value);
}

#[test]
fn textbook_r_mtcars_mpg_by_transmission_ties() {
    // R: wilcox.test(mpg ~ am, data = mtcars) (mtcars from R's datasets package; am = 0
    // automatic, 1 manual). Ties (e.g. 10.4, 15.2, 19.2, 21.4, 22.8, 30.4), so R uses the
    // normal approximation with continuity correction. Published output (stats.stackexchange
    // question 290830, "wilcox.test gives different results when using formula"):
    // p.value = 0.001871391.
    let automatic = [
        21.4, 18.7, 18.1, 14.3, 24.4, 22.8, 19.2, 17.8, 16.4, 17.3, 15.2, 10.4, 10.4, 14.7, 21.5, 15.5, 15.2, 13.3,
        19.2,
    ];
    let manual = [21.0, 21.0, 22.8, 32.4, 30.4, 33.9, 27.3, 26.0, 30.4, 15.8, 19.7, 15.0, 21.4];
    let r = rank_sum_test(&automatic, &manual);
    assert_eq!(r.method, Method::Normal);
    assert_eq!(r.u_x, 42.0);
    assert_abs(r.p_value, 0.001871391, 0.5e-9, "published p (9 d.p.)");
    // scipy 1.17.1: mannwhitneyu(automatic, manual, alternative='two-sided',
    // method='asymptotic', use_continuity=True) -> 42.0, 0.0018713913331785542.
    assert_rel(r.p_value, 0.0018713913331785542, 1e-6, "scipy asymptotic (relative)");
    assert!(r.z.unwrap() < 0.0);
}

#[test]
fn textbook_r_wilcox_examples_with_ties() {
    // Published R output (endmemo.com/r/wilcoxon.php, "R wilcox.test"), both with the warning
    // "cannot compute exact p-value with ties":
    //   wilcox.test(x, y)  -> W = 51.5, p-value = 0.5966
    //   wilcox.test(x, y2) -> W = 0,    p-value = 0.001364
    let x = [1.0, 5.0, 9.0, 24.0, 56.0, 21.0, 3.0, 7.0, 21.0, 4.0];
    let y = [12.0, 15.0, 5.0, 9.0, 9.0, 14.0, 56.0, 22.0, 3.0, 7.0, 32.0, 5.0];
    let y2 = [1233.0, 4356.0, 987.0, 39999.0, 1111.0, 200000.0];
    let r = rank_sum_test(&x, &y);
    assert_eq!(r.method, Method::Normal);
    assert_eq!(r.u_x, 51.5);
    assert_abs(r.p_value, 0.5966, 0.5e-4, "published p (4 d.p.)");
    // scipy 1.17.1: mannwhitneyu(x, y, alternative='two-sided', method='asymptotic',
    // use_continuity=True) -> 51.5, 0.5965969026279817.
    assert_rel(r.p_value, 0.5965969026279817, 1e-6, "scipy asymptotic (relative)");

    let r = rank_sum_test(&x, &y2);
    assert_eq!(r.method, Method::Normal); // the tie (21, 21) is inside x
    assert_eq!(r.u_x, 0.0);
    assert_abs(r.p_value, 0.001364, 0.5e-6, "published p (6 d.p.)");
    // scipy 1.17.1: mannwhitneyu(x, y2, alternative='two-sided', method='asymptotic',
    // use_continuity=True) -> 0.0, 0.0013643929543816092.
    assert_rel(r.p_value, 0.0013643929543816092, 1e-6, "scipy asymptotic (relative)");
}

#[test]
fn r_airquality_ozone_may_vs_august() {
    // R's ?wilcox.test formula example:
    // wilcox.test(Ozone ~ Month, data = airquality, subset = Month %in% c(5, 8)),
    // NA removed (26 days each). Only scipy's value is asserted here; R's printed output was
    // not available to check when this test was written.
    let may = [
        41.0, 36.0, 12.0, 18.0, 28.0, 23.0, 19.0, 8.0, 7.0, 16.0, 11.0, 14.0, 18.0, 14.0, 34.0, 6.0, 30.0, 11.0, 1.0,
        11.0, 4.0, 32.0, 23.0, 45.0, 115.0, 37.0,
    ];
    let august = [
        39.0, 9.0, 16.0, 78.0, 35.0, 66.0, 122.0, 89.0, 110.0, 44.0, 28.0, 65.0, 22.0, 59.0, 23.0, 31.0, 44.0, 21.0,
        9.0, 45.0, 168.0, 73.0, 76.0, 118.0, 84.0, 85.0,
    ];
    let r = rank_sum_test(&may, &august);
    assert_eq!(r.method, Method::Normal);
    assert_eq!(r.u_x, 127.5);
    // scipy 1.17.1: mannwhitneyu(may, august, alternative='two-sided',
    // method='asymptotic', use_continuity=True) -> 127.5, 0.00012080783076877434.
    assert_rel(r.p_value, 0.00012080783076877434, 1e-6, "scipy asymptotic (relative)");
}
