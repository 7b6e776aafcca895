//! The memoir's table of contents (pages 189–192): its parts, chapters and §, each with the
//! n° it holds ([`OUTLINE`]), by which the reports group their entries.

/// One § of the memoir's table of contents: the first and last n° it holds, its part, chapter
/// and § titles (as printed, in French).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Division {
    /// First n° of the §.
    pub first: u32,
    /// Last n° of the §.
    pub last: u32,
    /// The part (*Première partie — cerceau et monocycle*).
    pub part: &'static str,
    /// The chapter.
    pub chapter: &'static str,
    /// The §.
    pub paragraph: &'static str,
}

const P1: &str = "Première partie — cerceau et monocycle";
const P2: &str = "Deuxième partie — bicyclettes et bicycles";

macro_rules! division {
    ($first:expr, $last:expr, $part:expr, $chapter:expr, $paragraph:expr) => {
        Division {
            first: $first,
            last: $last,
            part: $part,
            chapter: $chapter,
            paragraph: $paragraph,
        }
    };
}

/// The memoir's table of contents (pages 189–192), n° 1 to 124.
pub const OUTLINE: [Division; 23] = [
    division!(1, 4, P1, "Chapitre I — cerceau", "§ I — cinématique du cerceau"),
    division!(5, 7, P1, "Chapitre I — cerceau", "§ II — équations du roulement du cerceau"),
    division!(
        8,
        11,
        P1,
        "Chapitre I — cerceau",
        "§ III — équilibre du régime du cerceau, stabilité, dérapage"
    ),
    division!(12, 16, P1, "Chapitre I — cerceau", "§ IV — discussion des états d'équilibre"),
    division!(17, 19, P1, "Chapitre I — cerceau", "§ V — complément pratique à la discussion"),
    division!(
        20,
        24,
        P1,
        "Chapitre II — monocycle",
        "§ I — équations différentielles du mouvement"
    ),
    division!(
        25,
        28,
        P1,
        "Chapitre II — monocycle",
        "§ II — marche du monocycle et des cycles en général"
    ),
    division!(29, 32, P1, "Chapitre II — monocycle", "§ III — équilibre du monocycle"),
    division!(33, 41, P1, "Chapitre II — monocycle", "§ IV — stabilité du monocycle"),
    division!(42, 42, P1, "Chapitre II — monocycle", "Conclusion : principe d'un monocycle stable"),
    division!(
        43,
        49,
        P2,
        "Chapitre I — géométrie de la bicyclette",
        "§ I — introduction, équations du problème"
    ),
    division!(
        50,
        55,
        P2,
        "Chapitre I — géométrie de la bicyclette",
        "§ II — cas où le cadre demeure vertical"
    ),
    division!(
        56,
        58,
        P2,
        "Chapitre I — géométrie de la bicyclette",
        "§ III — cas où le cadre n'est pas vertical"
    ),
    division!(59, 66, P2, "Chapitre II — cinématique et statique", "§ I — propriétés cinématiques"),
    division!(67, 70, P2, "Chapitre II — cinématique et statique", "§ II — équilibre au repos"),
    division!(
        71,
        74,
        P2,
        "Chapitre III — nouvelles méthodes",
        "§ I — méthode de Lagrange adaptée aux cycles"
    ),
    division!(
        75,
        78,
        P2,
        "Chapitre III — nouvelles méthodes",
        "§ II — méthode générale pour la stabilité"
    ),
    division!(
        79,
        89,
        P2,
        "Chapitre IV — dynamique de la bicyclette",
        "§ I — équilibre avec les mains"
    ),
    division!(
        90,
        98,
        P2,
        "Chapitre IV — dynamique de la bicyclette",
        "§ II — équilibre sans les mains"
    ),
    division!(
        99,
        106,
        P2,
        "Chapitre IV — dynamique de la bicyclette",
        "§ III — stabilité de l'équilibre avec les mains"
    ),
    division!(
        107,
        116,
        P2,
        "Chapitre IV — dynamique de la bicyclette",
        "§ IV — mouvement voisin de la marche rectiligne"
    ),
    division!(
        117,
        123,
        P2,
        "Chapitre IV — dynamique de la bicyclette",
        "§ V — stabilité de la marche rectiligne sans les mains"
    ),
    division!(124, 124, P2, "Chapitre IV — dynamique de la bicyclette", "Conclusions et résultats"),
];

/// The heading of entries that belong to no n° (symbolic checks `-`, the modern benchmark).
pub const BEYOND: &str = "Beyond the memoir's numbering (symbolic checks, modern benchmark)";

/// The § of the memoir that holds the section `section` (`"14"`, `"14/18"`, `"17 bis"`: the
/// first number counts); `None` for a section without a leading number.
pub fn division_of(section: &str) -> Option<&'static Division> {
    let digits: String = section.chars().take_while(|c| c.is_ascii_digit()).collect();
    let n: u32 = digits.parse().ok()?;
    OUTLINE.iter().find(|d| d.first <= n && n <= d.last)
}

/// The entries grouped by their division of the outline, the groups in the memoir's order and
/// the entries without a n° (or outside the outline) last; within a group, the entries' order.
pub fn by_division(
    entries: &[crate::entry::Entry],
) -> Vec<(Option<&'static Division>, Vec<&crate::entry::Entry>)> {
    let mut groups: Vec<(Option<&'static Division>, Vec<&crate::entry::Entry>)> = Vec::new();
    for e in entries {
        let d = division_of(&e.section);
        match groups.iter_mut().find(|(g, _)| *g == d) {
            Some((_, list)) => list.push(e),
            None => groups.push((d, vec![e])),
        }
    }
    groups.sort_by_key(|(d, _)| d.map_or(u32::MAX, |d| d.first));
    groups
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_outline_covers_every_number_once() {
        for n in 1..=124u32 {
            let hits = OUTLINE.iter().filter(|d| d.first <= n && n <= d.last);
            assert_eq!(hits.count(), 1, "n° {n}");
        }
        assert_eq!(division_of("17 bis").map(|d| d.first), Some(17));
        assert_eq!(division_of("14/18").map(|d| d.first), Some(12));
        assert_eq!(division_of("-"), None);
        assert_eq!(division_of("benchmark"), None);
    }
}
