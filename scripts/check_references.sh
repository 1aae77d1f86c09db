#!/usr/bin/env bash
# Checks that the citations in the tree resolve to entries of docs/references.md.
#
#   scripts/check_references.sh [--list]
#
# 1. Every seed citation in core/ shading/ apps/ bench/ fuzz/ tests/ docs/ scripts/ and README.md
#    (docs/references.md and this script excepted) must have an entry: "seed 000 eq. [24]" needs
#    the anchor seed-000-eq-24, "seed 000 eqs. [22]-[24]" needs seed-000-eq-22 … -24, "seed 003
#    eq. 2.8" seed-003-eq-2-8, "seed 003 ch. 3" seed-003-ch-3, "seed 003 §1.3" seed-003-sec-1-3,
#    "seed 003 fig. 3.13" seed-003-fig-3-13, a bare "seed 004" seed-004. A locator later on a line
#    that names a seed ("…; eq. 1.4") belongs to that seed when it is in that seed's numbering
#    style; a bare "eq. [28]" or "eqs. 1.9, 1.10" on a line naming no seed is seed 000's
#    (brackets) or seed 003's (1.x–3.x). Other bare "§", "ch." and "eq." (other books) are not
#    seed citations.
# 2. Every paper in the PAPERS list below must have its entry (anchor) in docs/references.md.
# 3. Every "Surname YEAR" / "Surname & Other YEAR" / "Surname et al. YEAR" in those files must be a
#    paper of the list (its "Surname YEAR" key), so that a new citation cannot go undocumented.
#
# Prints one summary line and exits 0 when everything resolves; otherwise lists each problem as
# file:line and exits 1. --list also prints every seed citation with the entries it resolves to.
# Needs bash, find and perl (core modules only); no network.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
refs="$root/docs/references.md"
list=0
case "${1:-}" in
  --list) list=1 ;;
  "") ;;
  -h|--help) sed -n '2,21p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
  *) echo "usage: $0 [--list]" >&2; exit 2 ;;
esac
if [[ ! -f "$refs" ]]; then
  echo "check_references: $refs is missing" >&2
  exit 1
fi

# The papers, books and specifications cited in the tree:
#   anchor ~ regex that finds a mention (Perl) ~ "Surname YEAR" keys that part 3 accepts
papers="$(mktemp)"
trap 'rm -f "$papers"' EXIT
cat >"$papers" <<'EOF'
amanatides-woo-1987 ~ Amanatides ~ Amanatides 1987, Woo 1987
ashikhmin-shirley-2000 ~ Ashikhmin ~ Ashikhmin 2000
beer-lambert ~ Beer.Lambert|beer_lambert|BeerLambert ~
blinn-1977 ~ Blinn 1977|SpecularModel::Blinn ~ Blinn 1977
blinn-1978 ~ Blinn 1978|Wrinkled Surfaces ~ Blinn 1978
burley-2012 ~ Burley 2012|Shading at Disney ~ Burley 2012
chen-asau-1974 ~ Chen (&|and) Asau ~ Chen 1974, Asau 1974
cohen-1988 ~ Cohen et al\.|Cohen, Chen ~ Cohen 1988
cohen-sutherland ~ Cohen.Sutherland ~
duff-2017 ~ Duff et al ~ Duff 2017
fnv-1a ~ FNV-1a ~
fresnel-1823 ~ Fresnel 1823|Fresnel equations|Fresnel reflectance ~ Fresnel 1823
frisvad-2012 ~ Frisvad ~ Frisvad 2012
geomview-off ~ geomview-off|Geomview's OFF ~
gltf-2.0 ~ glTF 2\.0 ~
gltf-pr-2392 ~ glTF#2392|glTF pull request #2392 ~
haines-1987 ~ Haines 1987|Standard Procedural Databases ~ Haines 1987
haines-1994 ~ Point in Polygon Strategies|Haines's crossing ~ Haines 1994
haines-nff ~ Neutral File Format|NFF specification ~
hanika-2021 ~ Hanika ~ Hanika 2021
hecht-2002 ~ Hecht ~ Hecht 2002
heitz-2014 ~ Heitz 2014|Masking-\s*Shadowing ~ Heitz 2014
heitz-2018 ~ Heitz 2018|Visible Normals ~ Heitz 2018
iec-61966-2-1 ~ IEC 61966-2-1 ~
kajiya-1986 ~ (?<!& )Kajiya 1986|rendering equation ~ Kajiya 1986
kay-kajiya-1986 ~ Kajiya ~ Kay 1986
khr-draco-mesh-compression ~ KHR_draco_mesh_compression ~
khr-lights-punctual ~ KHR_lights_punctual ~
khr-materials-clearcoat ~ KHR_materials_clearcoat ~
khr-materials-emissive-strength ~ KHR_materials_emissive_strength ~
khr-materials-ior ~ KHR_materials_ior ~
khr-texture-transform ~ KHR_texture_transform ~
lafortune-willems-1994 ~ Lafortune ~ Lafortune 1994
lambert-1760 ~ Lambert 1760|Lambert's (contour|formula) ~ Lambert 1760
law-kelton-2000 ~ batch means ~ Law 2000, Kelton 2000
lengyel-2001 ~ Lengyel ~ Lengyel 2001
lorensen-cline-1987 ~ Lorensen ~ Lorensen 1987
malley-1988 ~ Malley ~ Malley 1988
meisters-1975 ~ Meisters ~ Meisters 1975
mitchell-1990 ~ Mitchell 1990 ~ Mitchell 1990
moller-trumbore-1997 ~ Möller.Trumbore ~ Möller 1997
muller-2003 ~ Müller, Charypar ~ Müller 2003
newell-1975 ~ Utah teapot|Newell's Utah ~ Newell 1975
oneill-2014 ~ O'Neill|PCG32 ~ O'Neill 2014
pbrt-3 ~ \bpbrt|Pharr, Jakob ~ Pharr 2016
openexr ~ The OpenEXR File Layout|Reading and Writing OpenEXR ~
perlin-1985 ~ Perlin 1985 ~ Perlin 1985
perlin-2002 ~ Perlin 2002|Perlin's improved ~ Perlin 2002
phong-1975 ~ \bPhong\b ~ Phong 1975
png-spec ~ ISO/IEC 15948 ~
roth-1982 ~ Roth 1982 ~ Roth 1982
schlick-1994 ~ Schlick ~ Schlick 1994
shirley-1992 ~ Shirley's square-to-triangle ~ Shirley 1992
shirley-chiu-1997 ~ Shirley.{1,6}Chiu ~ Shirley 1997, Chiu 1997
snell-law ~ Snell ~
stl-1989 ~ stl-1989|StereoLithography Interface ~
sunday-2001 ~ Sunday's ~ Sunday 2001
sutherland-1974 ~ Sutherland, Sproull|Newell's (method|normal) ~ Sutherland 1974
taubin-1991 ~ Taubin ~ Taubin 1991
trowbridge-reitz-1975 ~ Trowbridge ~ Trowbridge 1975, Reitz 1975
turk-1994 ~ turk-1994|PLY Polygon File Format ~ Turk 1994
veach-guibas-1995 ~ Veach (&|and) Guibas|power heuristic ~ Veach 1995
veach-1997 ~ Veach ~ Veach 1997
wallace-1989 ~ Wallace et al|Wallace, Elmquist ~ Wallace 1989
walter-2007 ~ Walter et al|GGX ~ Walter 2007
wavefront-obj-mtl ~ Wavefront OBJ ~
wellons-2018 ~ Wellons|lowbias32 ~ Wellons 2018
whitted-1980 ~ Whitted ~ Whitted 1980
williams-1983 ~ Williams 1983|Pyramidal Parametrics ~ Williams 1983
wilson-hilferty-1931 ~ Wilson.{1,6}Hilferty|WilsonHilferty ~ Wilson 1931, Hilferty 1931
woop-2013 ~ Woop ~ Woop 2013, Benthin 2013, Wald 2013
worley-1996 ~ Worley ~ Worley 1996
wyvill-1986 ~ Wyvill ~ Wyvill 1986
EOF

cd "$root"
dirs=()
for d in core shading apps bench fuzz tests docs scripts; do [[ -d $d ]] && dirs+=("$d"); done
mapfile -t files < <(
  { if ((${#dirs[@]})); then
      find "${dirs[@]}" -type f \( -name '*.h' -o -name '*.hpp' -o -name '*.cpp' -o -name '*.cc' \
        -o -name '*.c' -o -name '*.md' -o -name '*.py' -o -name '*.sh' -o -name '*.txt' \
        -o -name '*.cmake' \) ! -path docs/references.md ! -path scripts/check_references.sh
    fi
    [[ -f README.md ]] && echo README.md
  } | LC_ALL=C sort)

perl -COEA - "$refs" "$papers" "$list" "${files[@]}" <<'PERL'
use strict;
use warnings;
use utf8;

my ($refs, $papers_file, $list, @files) = @ARGV;

my %anchor;
open my $rf, '<:encoding(UTF-8)', $refs or die "cannot read $refs: $!\n";
while (<$rf>) { $anchor{$1} = 1 while /<a id="([^"]+)"><\/a>/g; }
close $rf;

my (@papers, %known);
open my $pf, '<:encoding(UTF-8)', $papers_file or die;
while (<$pf>) {
    chomp;
    next if /^\s*(#|$)/;
    my ($id, $re, $keys) = map { s/^\s+|\s+$//gr } split /~/, $_, 3;
    push @papers, { id => $id, re => qr/$re/, seen => 0 };
    $known{$_} = 1 for grep { length } map { s/^\s+|\s+$//gr } split /,/, ($keys // '');
}
close $pf;
# "Name YEAR" shapes that are not literature citations.
my %not_a_citation = map { $_ => 1 } ('At 2048', 'Found 2026', 'Measured 2026');

my $dash = qr/\s*[-–—]\s*/;
my $br = qr/\[\d+\](?:$dash\[\d+\])?/;             # [24] or [22]-[24]
my $dot = qr/\d+(?:\.\d+)+(?:$dash\d+(?:\.\d+)+)?/; # 2.8, 4.2.3.1, 1.3–1.5
my $int = qr/\d+(?!\.\d)(?:$dash\d+(?!\.\d))?/;      # 3
my $sep = qr/(?:\s*[,\/]\s*(?:and\s+|or\s+)?|\s+(?:and|or)\s+)/;
my $keyword = qr/(?<![\w.])(eqs?\.|equations?|figs?\.|figures?|ch\.|chapters?|§)\s*/;

# The IDs one locator item stands for (ranges expanded).
sub expand {
    my ($seed, $kind, $item) = @_;
    my $prefix = "seed-$seed-$kind-";
    my @ends = split $dash, $item;
    s/[\[\]]//g for @ends;
    if (@ends == 2) {
        my @a = split /\./, $ends[0];
        my @b = split /\./, $ends[1];
        if (@a == @b && join('.', @a[0 .. $#a - 1]) eq join('.', @b[0 .. $#b - 1])
            && $b[-1] >= $a[-1] && $b[-1] - $a[-1] <= 60) {
            my @head = @a[0 .. $#a - 1];
            return map { $prefix . join('-', @head, $_) } $a[-1] .. $b[-1];
        }
    }
    return map { $prefix . join('-', split /\./) } @ends;
}

# Parses the item list that starts at the beginning of $text (after a keyword). Returns the
# items and the length consumed. Later items must have the first one's style.
sub items {
    my ($text, $kind) = @_;
    my ($style, $first);
    if ($kind eq 'eq') {
        ($text =~ /^($br)/ and ($style, $first) = ($br, $1))
            or ($text =~ /^($dot)/ and ($style, $first) = ($dot, $1))
            or ($text =~ /^($int)/ and ($style, $first) = ($int, $1));
    } elsif ($kind eq 'ch') {
        $text =~ /^($int)/ and ($style, $first) = ($int, $1);
    } else {    # sec, fig
        ($text =~ /^($dot)/ and ($style, $first) = ($dot, $1))
            or ($text =~ /^($int)/ and ($style, $first) = ($int, $1));
    }
    return () unless defined $first;
    my @items = ($first);
    my $used = length $first;
    while (substr($text, $used) =~ /^($sep)($style)/) {
        last if $style == $int && $kind eq 'eq';
        push @items, $2;
        $used += length($1) + length($2);
    }
    return (\@items, $used);
}

sub kind_of {
    my ($k) = @_;
    return 'eq' if $k =~ /^eq/;
    return 'fig' if $k =~ /^fig/;
    return 'ch' if $k =~ /^ch/;
    return 'sec';
}

# Whether a locator in a seed's numbering style (for locators not written right after the seed).
sub style_fits {
    my ($seed, $kind, $first) = @_;
    my $bracket = $first =~ /^\[/;
    my ($major) = $first =~ /^\[?(\d+)/;
    return $bracket if $seed eq '000' && $kind eq 'eq';
    return !$bracket && $major == 1 if $seed eq '000' && $kind eq 'sec';
    return $bracket if $seed eq '001' && $kind eq 'eq';
    return $major == 8 if $seed eq '001' && $kind eq 'sec';
    if ($seed eq '003') {
        return 0 if $bracket;
        return $major >= 1 && $major <= 3 && ($kind eq 'ch' || $first =~ /\./);
    }
    return !$bracket && $major == 4 if $seed eq '004' && $kind eq 'sec';
    return !$bracket && $first !~ /\./ if $seed eq '004' && $kind eq 'eq';
    return 0;
}

my (@cites, @problems, %distinct);
for my $file (@files) {
    open my $fh, '<:encoding(UTF-8)', $file or next;
    my $n = 0;
    while (my $line = <$fh>) {
        ++$n;
        chomp $line;
        for my $p (@papers) { $p->{seen} = 1 if !$p->{seen} && $line =~ $p->{re}; }
        while ($line =~ /\b((?:\p{Lu}['’])?\p{Lu}\p{Ll}+)(?:(?:, | & | and )\p{Lu}\p{Ll}+)*(?: et al\.?)?,? \(?((?:1[6-9]|20)\d\d)\b(?![-:\d])/g) {
            my $key = "$1 $2";
            push @problems, "$file:$n: \"$key\" looks like a literature citation that is not in "
                . "the PAPERS list of scripts/check_references.sh (add it there and an entry to "
                . "docs/references.md)"
                unless $known{$key} || $not_a_citation{$key};
        }
        next unless $line =~ /seed|eqs?\.|figs?\./i;

        # Seed mentions, in order, with a locator written right after them.
        my @events;
        while ($line =~ /\b[Ss]eeds?\s+(0\d\d)\b((?:'s|’s)?)/g) {
            push @events, { pos => $-[0], end => $+[0], seed => $1, direct => 1 };
        }
        while ($line =~ /$keyword/g) {
            push @events, { pos => $-[0], end => $+[0], kw => $1 };
        }
        @events = sort { $a->{pos} <=> $b->{pos} } @events;
        my $current;
        my %claimed;    # keyword positions consumed by a seed's direct locator
        for my $i (0 .. $#events) {
            my $e = $events[$i];
            if (defined $e->{seed}) {
                $current = $e->{seed};
                my $rest = substr($line, $e->{end});
                my @ids;
                my $text;
                if ($rest =~ /^([\s,(]*)$keyword/) {
                    my ($lead, $whole, $kind) = (length $1, length $&, kind_of($2));
                    my ($items, $used) = items(substr($rest, $whole), $kind);
                    if ($items) {
                        @ids = map { expand($e->{seed}, $kind, $_) } @$items;
                        $text = substr($line, $e->{pos}, $e->{end} - $e->{pos} + $whole + $used);
                        $claimed{ $e->{end} + $lead } = 1;
                    }
                } elsif ($rest =~ /^(\s*)($br(?:$sep$br)*)/) {    # "seed 000 [24]"
                    my $list = $2;
                    @ids = map { expand($e->{seed}, 'eq', $_) } ($list =~ /($br)/g);
                    $text = substr($line, $e->{pos}, $e->{end} - $e->{pos} + length($1) + length($list));
                }
                unless (@ids) {
                    @ids = ("seed-$e->{seed}");
                    $text = substr($line, $e->{pos}, $e->{end} - $e->{pos});
                }
                push @cites, { where => "$file:$n", text => $text, ids => \@ids };
                next;
            }
            next if $claimed{$e->{pos}};
            my $kind = kind_of($e->{kw});
            my ($items, $used) = items(substr($line, $e->{end}), $kind);
            next unless $items;
            my $seed;
            if (defined $current) {
                $seed = $current if style_fits($current, $kind, $items->[0]);
            } elsif ($kind eq 'eq' || $kind eq 'fig') {
                if ($items->[0] =~ /^\[/) { $seed = '000' if $kind eq 'eq'; }
                elsif ($items->[0] =~ /^([123])\.\d/) { $seed = '003'; }
            }
            next unless defined $seed;
            my @ids = map { expand($seed, $kind, $_) } @$items;
            push @cites, { where => "$file:$n",
                           text => substr($line, $e->{pos}, $e->{end} - $e->{pos} + $used)
                               . " (seed $seed)",
                           ids => \@ids };
        }
    }
    close $fh;
}

my $unresolved = 0;
for my $c (@cites) {
    my @missing = grep { !$anchor{$_} } @{ $c->{ids} };
    $distinct{$_} = 1 for @{ $c->{ids} };
    print "$c->{where}: $c->{text} -> @{ $c->{ids} }\n" if $list;
    if (@missing) {
        ++$unresolved;
        push @problems, "$c->{where}: \"$c->{text}\" has no entry in docs/references.md "
            . "(missing: @missing)";
    }
}
for my $p (@papers) {
    push @problems, "scripts/check_references.sh: paper \"$p->{id}\" has no entry in "
        . "docs/references.md" unless $anchor{ $p->{id} };
}
my @uncited = map { $_->{id} } grep { !$_->{seen} } @papers;

my $n_cites = scalar @cites;
my $n_distinct = scalar keys %distinct;
my $n_papers = scalar @papers;
if (@problems) {
    print STDERR "$_\n" for @problems;
    print STDERR "check_references: $n_cites citations, $n_distinct distinct, $unresolved "
        . "unresolved; " . scalar(@problems) . " problem(s)\n";
    exit 1;
}
print "note: listed but no longer found in the tree: @uncited\n" if @uncited;
print "$n_cites citations, $n_distinct distinct, all resolve; $n_papers papers and "
    . "specifications listed, all have entries\n";
PERL
