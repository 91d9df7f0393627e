use super::*;
use crate::compare::from_records;

#[test]
fn shares_are_parsed_and_bad_ones_name_the_flag_and_value() {
    assert_eq!(Share::parse("2/3").unwrap(), Share { k: 2, n: 3 });
    assert_eq!(Share::parse("1/1").unwrap(), Share { k: 1, n: 1 });
    for bad in ["0/3", "4/3", "a/b", "3", "1/0", "-1/3", "1/3/5", ""] {
        let e = Share::parse(bad).unwrap_err().to_string();
        assert!(e.starts_with("--shard: '") && e.contains(&format!("'{bad}'")), "{bad}: {e}");
    }
}

/// 7 runs in 3 shares: run i goes to share (i mod 3) + 1, so shares 1, 2, 3 get runs
/// {0, 3, 6}, {1, 4} and {2, 5}, every run exactly once.
#[test]
fn runs_are_dealt_round_robin() {
    let runs: Vec<usize> = (0..7).collect();
    let shares: Vec<Vec<usize>> = (1..=3).map(|k| Share { k, n: 3 }.select(runs.clone())).collect();
    assert_eq!(shares, [vec![0, 3, 6], vec![1, 4], vec![2, 5]]);
    let sizes: Vec<usize> = (1..=3).map(|k| Share { k, n: 3 }.size(7)).collect();
    assert_eq!(sizes, [3, 2, 2]);
    assert!(Share { k: 2, n: 3 }.owns(4) && !Share { k: 2, n: 3 }.owns(5));
}

/// Hand-made records of 2 planners x 3 runs on `bay`, master seed 0, costs 1 to 6.
fn whole() -> Comparison {
    let all = tasks(0, &["bay".into()], &["pso".into(), "de".into()], 3);
    let records = all
        .iter()
        .enumerate()
        .map(|(i, t)| RunRecord {
            problem: t.problem.clone(),
            planner: t.planner.clone(),
            run: t.run,
            seed: t.seed,
            cost: 1.0 + i as f64,
            feasible: true,
            elapsed_s: 0.5,
            ..RunRecord::default()
        })
        .collect();
    from_records("scenario", &["bay"], &["pso", "de"], 3, records)
}

/// Shard `k` of `n` of `c`, as `compare --shard` writes it.
fn shard(c: &Comparison, k: u64, n: u64) -> ShardResults {
    let share = Share { k, n };
    let records = share.select(c.records.clone());
    let mut part = c.clone();
    part.finished_runs = records.len();
    part.records = records;
    let info = ShardInfo {
        k,
        n,
        share_runs: share.size(c.planned_runs()),
        scenario: "builtin:bay".into(),
        scenario_hash: "00000000000000aa".into(),
        encoding_hash: "00000000000000bb".into(),
    };
    ShardResults { dir: format!("part-{k}"), file: ShardFile { comparison: part, shard: Some(info) } }
}

fn error(shards: &[ShardResults]) -> String {
    merge(shards).unwrap_err().to_string()
}

#[test]
fn shards_in_any_order_join_into_the_whole_comparison() {
    let c = whole();
    let (merged, info) = merge(&[shard(&c, 3, 3), shard(&c, 1, 3), shard(&c, 2, 3)]).unwrap();
    assert_eq!(merged.records, c.records);
    let costs: Vec<f64> = merged.records.iter().map(|r| r.cost).collect();
    assert_eq!(costs, [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    assert_eq!(crate::output::table_md(&merged), crate::output::table_md(&c));
    assert!(merged.complete && merged.finished_runs == 6);
    // The shards' wall times add up: 3 x 0.0 from `from_records`' clock, near enough zero.
    assert!(merged.total_wall_s < 1.0);
    assert_eq!((info.n, info.scenario_argument()), (3, "bay"));
}

#[test]
fn a_missing_duplicated_foreign_or_incomplete_shard_is_named() {
    let c = whole();
    assert_eq!(error(&[shard(&c, 1, 3), shard(&c, 3, 3)]), "DIR: shard 2/3 is missing");
    assert_eq!(
        error(&[shard(&c, 1, 3), shard(&c, 2, 3), shard(&c, 2, 3), shard(&c, 3, 3)]),
        "DIR: shard 2/3 is given twice: 'part-2' and 'part-2'"
    );
    let mut other = shard(&c, 2, 3);
    other.file.comparison.master_seed = 7;
    assert_eq!(
        error(&[shard(&c, 1, 3), other, shard(&c, 3, 3)]),
        "DIR: shard 2/3 ('part-2') differs in master seed: 7; shard 1/3 ('part-1') has 0"
    );
    let mut two = shard(&c, 2, 2);
    two.file.shard.as_mut().unwrap().n = 2;
    assert!(error(&[shard(&c, 1, 3), two]).contains("differs in the shard count N: 2;"));
    let mut cut = shard(&c, 3, 3);
    cut.file.comparison.complete = false;
    cut.file.comparison.finished_runs = 1;
    assert_eq!(
        error(&[shard(&c, 1, 3), shard(&c, 2, 3), cut]),
        "DIR: shard 3/3 ('part-3') is incomplete (1 of 2 runs finished); run it again"
    );
    let mut whole_file = shard(&c, 1, 1);
    whole_file.file.shard = None;
    assert_eq!(error(&[whole_file]), "DIR: 'part-1' holds no shard (its results.json has no `shard` block)");
}

#[test]
fn a_shard_holding_other_runs_is_refused() {
    let c = whole();
    let mut swapped = shard(&c, 2, 3);
    swapped.file.comparison.records.swap(0, 1);
    let e = error(&[shard(&c, 1, 3), swapped, shard(&c, 3, 3)]);
    // Share 2 of 3 holds runs 1 and 4 of the six: pso's run 1, then de's run 1.
    assert!(
        e.starts_with("DIR: shard 2/3 ('part-2') has run 1 of de on bay (seed ") && e.contains("where run 1 of pso"),
        "{e}"
    );
    let mut short = shard(&c, 3, 3);
    short.file.comparison.records.pop();
    let e = error(&[shard(&c, 1, 3), shard(&c, 2, 3), short]);
    assert!(e.starts_with("DIR: shard 3/3 ('part-3') lacks run 2 of de on bay"), "{e}");
}

/// The shard block rides beside the comparison's own fields, and a whole comparison's
/// results.json reads as a file without one.
#[test]
fn the_shard_block_round_trips_beside_the_comparison() {
    let c = whole();
    let s = shard(&c, 2, 3);
    let text = s.file.json();
    let back: ShardFile = serde_json::from_str(&text).unwrap();
    assert_eq!(back.shard, s.file.shard);
    assert_eq!(back.comparison.records, s.file.comparison.records);
    let plain: ShardFile = serde_json::from_str(&crate::output::results_json(&c)).unwrap();
    assert!(plain.shard.is_none());
}

/// Costs read back from a shard's results.json are the bits that were written (serde_json's
/// default float parsing is off by one unit in the last place for these two).
#[test]
fn costs_read_back_to_the_last_bit() {
    let mut c = whole();
    c.records[0].cost = 19.456462675541434;
    c.records[1].cost = 3860.6025770491315;
    let s = shard(&c, 1, 1);
    let back: ShardFile = serde_json::from_str(&s.file.json()).unwrap();
    let bits = |f: &ShardFile| f.comparison.records.iter().map(|r| r.cost.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&back), bits(&s.file));
}
