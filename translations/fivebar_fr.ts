<?xml version='1.0' encoding='utf-8'?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR">
    <context>
        <name>CalibrationWizard</name>
        <message>
            <source>Hoang's accuracy pattern (10 lines of 40 mm) does not fit in this machine's safe area.</source>
            <translation>Le motif de précision de Hoang (10 lignes de 40 mm) ne tient pas dans la zone sûre de cette machine.</translation>
        </message>
        <message>
            <source>The simulated machine drew %1 lines instead of %2.</source>
            <translation>La machine simulée a tracé %1 lignes au lieu de %2.</translation>
        </message>
        <message>
            <source>A simulated line is too short to measure.</source>
            <translation>Une ligne simulée est trop courte pour être mesurée.</translation>
        </message>
    </context>
    <context>
        <name>Design</name>
        <message>
            <source>%1 must be a positive length in mm</source>
            <translation>%1 doit être une longueur positive en mm</translation>
        </message>
        <message>
            <source>the rectangle's width</source>
            <translation>la largeur du rectangle</translation>
        </message>
        <message>
            <source>the rectangle's height</source>
            <translation>la hauteur du rectangle</translation>
        </message>
        <message>
            <source>the shortest link</source>
            <translation>le bras le plus court</translation>
        </message>
        <message>
            <source>the longest link</source>
            <translation>le bras le plus long</translation>
        </message>
        <message>
            <source>the shortest link (%1 mm) is longer than the longest (%2 mm)</source>
            <translation>le bras le plus court (%1 mm) est plus long que le plus long (%2 mm)</translation>
        </message>
        <message>
            <source>the motor spacing must be 0 mm or more</source>
            <translation>l'écart entre les moteurs doit être de 0 mm ou plus</translation>
        </message>
        <message>
            <source>the smallest motor spacing (%1 mm) exceeds the largest (%2 mm)</source>
            <translation>le plus petit écart entre les moteurs (%1 mm) dépasse le plus grand (%2 mm)</translation>
        </message>
        <message>
            <source>the clearance must be 0 mm or more</source>
            <translation>la marge de dégagement doit être de 0 mm ou plus</translation>
        </message>
        <message>
            <source>the type II margin must be from 0 to below 90 deg</source>
            <translation>la marge de type II doit être comprise entre 0 et moins de 90°</translation>
        </message>
        <message>
            <source>mix weights must be finite and not negative</source>
            <translation>les poids du mélange doivent être finis et non négatifs</translation>
        </message>
        <message>
            <source>mix weights must not all be zero</source>
            <translation>les poids du mélange ne doivent pas être tous nuls</translation>
        </message>
    </context>
    <context>
        <name>DesignPainter</name>
        <message>
            <source>Workspace, singularity-free region and type II curves</source>
            <translation>Espace de travail, zone sans singularité et courbes de type II</translation>
        </message>
        <message>
            <source>a1 = %1, b1 = %2, a2 = %3, b2 = %4, w = %5 mm, working mode %6</source>
            <translation>a1 = %1, b1 = %2, a2 = %3, b2 = %4, w = %5 mm, mode de travail %6</translation>
        </message>
        <message>
            <source>Rectangle x %1 .. %2, y %3 .. %4 mm; worst condition number %5 (mean %6)</source>
            <translation>Rectangle x %1 .. %2, y %3 .. %4 mm ; pire conditionnement %5 (moyenne %6)</translation>
        </message>
        <message>
            <source>Type II margin %1 deg, type I margin %2 deg, footprint %3 cm²</source>
            <translation>Marge type II %1°, marge type I %2°, encombrement %3 cm²</translation>
        </message>
        <message>
            <source>Worst %1 um per step, worst motor speed %2 deg/s</source>
            <translation>Pire %1 µm par pas, pire vitesse moteur %2°/s</translation>
        </message>
    </context>
    <context>
        <name>DocumentCommands</name>
        <message>
            <source>Import drawing</source>
            <translation>Importer le dessin</translation>
        </message>
        <message>
            <source>Move drawing</source>
            <translation>Déplacer le dessin</translation>
        </message>
        <message>
            <source>Change working mode</source>
            <translation>Changer le mode de travail</translation>
        </message>
        <message>
            <source>Change machine profile</source>
            <translation>Changer le profil de machine</translation>
        </message>
        <message>
            <source>Rotate drawing</source>
            <translation>Faire pivoter le dessin</translation>
        </message>
        <message>
            <source>Resize drawing</source>
            <translation>Redimensionner le dessin</translation>
        </message>
    </context>
    <context>
        <name>ImportError</name>
        <message>
            <source>%1 has a point at (%2, %3) mm, beyond the %4 mm limit</source>
            <translation>%1 a un point en (%2, %3) mm, au-delà de la limite de %4 mm</translation>
        </message>
        <message>
            <source>%1 has a non-finite coordinate</source>
            <translation>%1 a une coordonnée non finie</translation>
        </message>
        <message>
            <source>%1 (%2)</source>
            <translation>%1 (%2)</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1 : %2</translation>
        </message>
        <message>
            <source>%1: nesting deeper than %2 elements</source>
            <translation>%1 : imbrication de plus de %2 éléments</translation>
        </message>
        <message>
            <source>%1: the root element is not &lt;svg&gt;</source>
            <translation>%1 : l'élément racine n'est pas &lt;svg&gt;</translation>
        </message>
        <message>
            <source>cannot open: %1</source>
            <translation>impossible d'ouvrir : %1</translation>
        </message>
        <message>
            <source>cannot read: %1</source>
            <translation>impossible de lire : %1</translation>
        </message>
        <message>
            <source>compressed SVG (gzip): %1</source>
            <translation>SVG compressé (gzip) : %1</translation>
        </message>
        <message>
            <source>could not create a pipe for the SVG worker: %1</source>
            <translation>impossible de créer un tube pour le processus SVG : %1</translation>
        </message>
        <message>
            <source>could not start the SVG worker %1: %2</source>
            <translation>impossible de lancer le processus SVG %1 : %2</translation>
        </message>
        <message>
            <source>import cancelled</source>
            <translation>import annulé</translation>
        </message>
        <message>
            <source>layer "%1" has a non-finite coordinate</source>
            <translation>le calque « %1 » a une coordonnée non finie</translation>
        </message>
        <message>
            <source>layer "%1" has a point at (%2, %3) mm, beyond the %4 mm limit</source>
            <translation>le calque « %1 » a un point en (%2 ; %3) mm, au-delà de la limite de %4 mm</translation>
        </message>
        <message>
            <source>line %1, column %2: %3</source>
            <translation>ligne %1, colonne %2 : %3</translation>
        </message>
        <message>
            <source>line %1: %2</source>
            <translation>ligne %1 : %2</translation>
        </message>
        <message>
            <source>line %1: &lt;%2&gt; attribute %3 contains a value that is not a number (%4)</source>
            <translation>ligne %1 : &lt;%2&gt; l'attribut %3 contient une valeur qui n'est pas un nombre (%4)</translation>
        </message>
        <message>
            <source>line %1: &lt;%2&gt; attribute %3 contains a number beyond 1e300 (%4)</source>
            <translation>ligne %1 : &lt;%2&gt; l'attribut %3 contient un nombre au-delà de 1e300 (%4)</translation>
        </message>
        <message>
            <source>line %1: &lt;%2&gt;</source>
            <translation>ligne %1 : &lt;%2&gt;</translation>
        </message>
        <message>
            <source>more than %1 points after flattening (the points budget): reading stopped there</source>
            <translation>plus de %1 points après aplatissement (le budget de points) : lecture arrêtée là</translation>
        </message>
        <message>
            <source>no &lt;svg&gt; element found</source>
            <translation>aucun élément &lt;svg&gt; trouvé</translation>
        </message>
        <message>
            <source>no such file</source>
            <translation>fichier introuvable</translation>
        </message>
        <message>
            <source>not readable</source>
            <translation>illisible</translation>
        </message>
        <message>
            <source>root &lt;svg&gt; %1="%2" is not a length</source>
            <translation>&lt;svg&gt; racine : %1="%2" n'est pas une longueur</translation>
        </message>
        <message>
            <source>root &lt;svg&gt; %1="%2" is zero or negative: nothing to draw</source>
            <translation>&lt;svg&gt; racine : %1="%2" est nul ou négatif : rien à dessiner</translation>
        </message>
        <message>
            <source>root &lt;svg&gt; viewBox="%1": %2</source>
            <translation>&lt;svg&gt; racine : viewBox="%1" : %2</translation>
        </message>
        <message>
            <source>the SVG parser crashed on this file (it is hostile or corrupt, or needed more than the %1 MB memory limit)</source>
            <translation>l'analyseur SVG a planté sur ce fichier (il est malveillant ou corrompu, ou a demandé plus que la limite de %1 Mo de mémoire)</translation>
        </message>
        <message>
            <source>the SVG parser did not finish within %1 s and was stopped (the file is too complex or makes Qt SVG hang)</source>
            <translation>l'analyseur SVG n'a pas terminé en %1 s et a été arrêté (le fichier est trop complexe ou bloque Qt SVG)</translation>
        </message>
        <message>
            <source>the SVG worker (fivebar-svg-worker) was not found; set ImportOptions::workerPath or FIVEBAR_SVG_WORKER, or install it next to the program</source>
            <translation>le processus SVG (fivebar-svg-worker) est introuvable ; définissez ImportOptions::workerPath ou FIVEBAR_SVG_WORKER, ou installez-le à côté du programme</translation>
        </message>
        <message>
            <source>the SVG worker ended without a readable result (exit code %1): %2</source>
            <translation>le processus SVG s'est terminé sans résultat lisible (code de sortie %1) : %2</translation>
        </message>
        <message>
            <source>the compressed file is empty</source>
            <translation>le fichier compressé est vide</translation>
        </message>
        <message>
            <source>the file is empty</source>
            <translation>le fichier est vide</translation>
        </message>
    </context>
    <context>
        <name>ImportWarning</name>
        <message>
            <source>text in a single-stroke font: per-glyph x/y/dx/dy lists are not followed, only their first value</source>
            <translation>texte en police à trait simple : les listes x/y/dx/dy par glyphe ne sont pas suivies, seule leur première valeur</translation>
        </message>
        <message>
            <source>text in a single-stroke font: text on a path (&lt;textPath&gt;) is not drawn</source>
            <translation>texte en police à trait simple : le texte sur un chemin (&lt;textPath&gt;) n'est pas dessiné</translation>
        </message>
        <message>
            <source>text in a single-stroke font: only UTF-8 documents, this one is %1: its text is drawn as outlines</source>
            <translation>texte en police à trait simple : documents UTF-8 seulement, celui-ci est en %1 : son texte est dessiné en contours</translation>
        </message>
        <message>
            <source>clip-path set in a style sheet is not applied: those shapes are drawn unclipped</source>
            <translation>clip-path défini dans une feuille de style n’est pas appliqué : ces formes sont dessinées sans découpe</translation>
        </message>
        <message>
            <source>%1: its lines there are not drawn</source>
            <translation>%1 : ses lignes à cet endroit ne sont pas dessinées</translation>
        </message>
        <message>
            <source>lines outside the page (the SVG viewport) are not drawn: cut at its edge</source>
            <translation>les lignes hors de la page (le viewport SVG) ne sont pas dessinées : coupées à son bord</translation>
        </message>
        <message>
            <source>%1: the element is not drawn</source>
            <translation>%1 : l’élément n’est pas dessiné</translation>
        </message>
        <message>
            <source>attribute d: path data begins with "%1", not a moveto (M or m): in error from its first command, nothing drawn</source>
            <translation>attribut d : les données du chemin commencent par « %1 », pas par un moveto (M ou m) : en erreur dès la première commande, rien n’est dessiné</translation>
        </message>
        <message>
            <source>clip-path #%1 not found: drawn unclipped</source>
            <translation>clip-path #%1 introuvable : dessiné sans découpe</translation>
        </message>
        <message>
            <source>attribute d: invalid path data at character %1 %2: drawn up to the error</source>
            <translation>attribut d : données de tracé invalides au caractère %1 %2 : tracé jusqu'à l'erreur</translation>
        </message>
        <message>
            <source>attribute d: invalid path data at character %1: drawn up to the error</source>
            <translation>attribut d : données de tracé invalides au caractère %1 : tracé jusqu'à l'erreur</translation>
        </message>
        <message>
            <source>transform-origin="%1" not understood: ignored</source>
            <translation>transform-origin="%1" non compris : ignoré</translation>
        </message>
        <message>
            <source>marker #%1 not found: not drawn</source>
            <translation>marqueur #%1 introuvable : non tracé</translation>
        </message>
        <message>
            <source>markers on %1 are not drawn (drawn on path, line, polyline and polygon)</source>
            <translation>les marqueurs sur %1 ne sont pas tracés (tracés sur path, line, polyline et polygon)</translation>
        </message>
        <message>
            <source>markers set in a style sheet for the selector '%1' are not drawn (only type, #id and .class selectors are applied)</source>
            <translation>les marqueurs définis dans une feuille de style pour le sélecteur '%1' ne sont pas tracés (seuls les sélecteurs de type, #id et .class sont appliqués)</translation>
        </message>
        <message>
            <source>external reference removed from %1</source>
            <translation>référence externe supprimée de %1</translation>
        </message>
        <message>
            <source>%1 element removed</source>
            <translation>élément %1 supprimé</translation>
        </message>
        <message>
            <source>long &lt;path&gt; split into %1 parts to avoid Qt SVG's 32,767-element truncation</source>
            <translation>&lt;path&gt; long découpé en %1 parties pour éviter la troncature à 32 767 éléments de Qt SVG</translation>
        </message>
        <message>
            <source>further element warnings not listed</source>
            <translation>autres avertissements d'éléments non listés</translation>
        </message>
        <message>
            <source>DOCTYPE with entity declarations removed (internal entities were expanded)</source>
            <translation>DOCTYPE avec déclarations d'entités supprimé (les entités internes ont été développées)</translation>
        </message>
        <message>
            <source>unresolved entity reference dropped</source>
            <translation>référence d'entité non résolue abandonnée</translation>
        </message>
        <message>
            <source>external style sheet (xml-stylesheet) ignored</source>
            <translation>feuille de style externe (xml-stylesheet) ignorée</translation>
        </message>
        <message>
            <source>event attribute (on...) removed</source>
            <translation>attribut d'événement (on...) supprimé</translation>
        </message>
        <message>
            <source>CSS @import removed</source>
            <translation>@import CSS supprimé</translation>
        </message>
        <message>
            <source>transform-origin in a style is not applied</source>
            <translation>transform-origin dans un style n'est pas appliqué</translation>
        </message>
        <message>
            <source>mask not applied: masked shapes are drawn whole</source>
            <translation>masque non appliqué : les formes masquées sont tracées entières</translation>
        </message>
        <message>
            <source>per-glyph rotate on &lt;text&gt; is not applied: glyphs are drawn upright</source>
            <translation>la rotation par glyphe sur &lt;text&gt; n'est pas appliquée : les glyphes sont tracés droits</translation>
        </message>
        <message>
            <source>text on a path (&lt;textPath&gt;) is not drawn</source>
            <translation>le texte sur un chemin (&lt;textPath&gt;) n'est pas tracé</translation>
        </message>
        <message>
            <source>pattern fills are drawn as outlines, without the pattern</source>
            <translation>les remplissages à motif sont tracés en contour, sans le motif</translation>
        </message>
        <message>
            <source>more than 100000 marker instances: the rest are not drawn</source>
            <translation>plus de 100000 instances de marqueurs : les suivantes ne sont pas tracées</translation>
        </message>
        <message>
            <source>marker overflow clipping not applied: marker content is drawn whole</source>
            <translation>découpage du débordement des marqueurs non appliqué : leur contenu est tracé entier</translation>
        </message>
        <message>
            <source>no usable width/height/viewBox: page size taken from the drawing's extent</source>
            <translation>pas de width/height/viewBox utilisable : taille de page prise de l'étendue du dessin</translation>
        </message>
        <message>
            <source>line %1: %2 %3</source>
            <translation>ligne %1 : %2 %3</translation>
        </message>
        <message>
            <source>%1 (%2x, first at line %3)</source>
            <translation>%1 (%2x, première à la ligne %3)</translation>
        </message>
    </context>
    <context>
        <name>ImportWarningsPanel</name>
        <message>
            <source>%1 has %2 points after flattening, more than the budget of %3 (a runaway file?).</source>
            <translation>%1 a %2 points après aplatissement, plus que le budget de %3 (un fichier hors de contrôle ?).</translation>
        </message>
        <message>
            <source>Very large drawing</source>
            <translation>Dessin très grand</translation>
        </message>
        <message>
            <source>Planning and plotting it may take very long. Import it anyway?</source>
            <translation>Sa planification et son tracé peuvent être très longs. L'importer quand même ?</translation>
        </message>
    </context>
    <context>
        <name>JobPipeline</name>
        <message>
            <source>Nothing to plan: the drawing has no visible path.</source>
            <translation>Rien à planifier : le dessin n'a aucun tracé visible.</translation>
        </message>
        <message>
            <source>Planning cancelled.</source>
            <translation>Planification annulée.</translation>
        </message>
        <message>
            <source>Planned in working mode %1.</source>
            <translation>Planifié dans le mode de travail %1.</translation>
        </message>
        <message>
            <source>This job is long: about %1 hours and %2 pen-down moves. The machine will be busy all that time. Start it anyway?</source>
            <translation>Cette tâche est longue : environ %1 heures et %2 mouvements stylo baissé. La machine sera occupée tout ce temps. La lancer quand même ?</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1 : %2</translation>
        </message>
        <message>
            <source>%1: cannot write a temporary copy to import</source>
            <translation>%1 : impossible d'écrire une copie temporaire pour l'import</translation>
        </message>
        <message>
            <source>%1: cannot be imported</source>
            <translation>%1 : ne peut pas être importé</translation>
        </message>
        <message>
            <source>%1: cannot read (%2)</source>
            <translation>%1 : lecture impossible (%2)</translation>
        </message>
        <message>
            <source>no machine profile given</source>
            <translation>aucun profil de machine indiqué</translation>
        </message>
    </context>
    <context>
        <name>MapPainter</name>
        <message>
            <source>Transmission angle at the pen (deg)</source>
            <translation>Angle de transmission au stylo (°)</translation>
        </message>
        <message>
            <source>Conditioning (1 = isotropic)</source>
            <translation>Conditionnement (1 = isotrope)</translation>
        </message>
        <message>
            <source>Resolution (um per motor step)</source>
            <translation>Résolution (µm par pas moteur)</translation>
        </message>
    </context>
    <context>
        <name>Placement</name>
        <message>
            <source>scaled to %1 % to fit the workspace</source>
            <translation>réduit à %1 % pour tenir dans l'espace de travail</translation>
        </message>
    </context>
    <context>
        <name>Planner</name>
        <message>
            <source>layer '%1'</source>
            <translation>calque « %1 »</translation>
        </message>
        <message>
            <source>layer %1</source>
            <translation>calque %1</translation>
        </message>
        <message>
            <source>move or shrink the drawing (--at, --scale, --fit)</source>
            <translation>déplacer ou réduire le dessin (--at, --scale, --fit)</translation>
        </message>
        <message>
            <source>try another working mode (--mode)</source>
            <translation>essayer un autre mode de travail (--mode)</translation>
        </message>
        <message>
            <source>travel back to the start pose</source>
            <translation>retour à la position de départ</translation>
        </message>
        <message>
            <source>start pose</source>
            <translation>position de départ</translation>
        </message>
        <message>
            <source>the profile's home pose does not close the linkage</source>
            <translation>la position d'origine du profil ne ferme pas le mécanisme</translation>
        </message>
        <message>
            <source>set a reachable home pose in the profile</source>
            <translation>définir une position d'origine atteignable dans le profil</translation>
        </message>
        <message>
            <source>a point is out of reach in working mode %1</source>
            <translation>un point est hors de portée en mode de travail %1</translation>
        </message>
        <message>
            <source>the drawn curve cannot follow the stroke here (singular region)</source>
            <translation>la courbe tracée ne peut pas suivre le trait ici (zone singulière)</translation>
        </message>
        <message>
            <source>the drawn line %1</source>
            <translation>la ligne tracée %1</translation>
        </message>
        <message>
            <source>travel to %1</source>
            <translation>déplacement vers %1</translation>
        </message>
        <message>
            <source>no safe pen-up travel reaches it</source>
            <translation>aucun déplacement sûr stylo levé ne l'atteint</translation>
        </message>
        <message>
            <source>move the drawing away from singular regions (--at)</source>
            <translation>éloigner le dessin des zones singulières (--at)</translation>
        </message>
        <message>
            <source>try another --mode</source>
            <translation>essayer un autre --mode</translation>
        </message>
        <message>
            <source>%1 path %2</source>
            <translation>%1 chemin %2</translation>
        </message>
        <message>
            <source>tolerance %1 mm leaves nothing for the moves after flattening (%2 mm) and the G-code rounding (up to %3 mm)</source>
            <translation>la tolérance de %1 mm ne laisse rien aux mouvements après l'aplatissement (%2 mm) et l'arrondi du G-code (jusqu'à %3 mm)</translation>
        </message>
        <message>
            <source>backlash compensation</source>
            <translation>compensation du jeu</translation>
        </message>
        <message>
            <source>move the drawing away from the workspace edge (--at)</source>
            <translation>éloigner le dessin du bord de l'espace de travail (--at)</translation>
        </message>
        <message>
            <source>planning cancelled</source>
            <translation>planification annulée</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1 : %2</translation>
        </message>
        <message>
            <source>backlash compensation: a compensated move %1</source>
            <translation>compensation du jeu : un mouvement compensé %1</translation>
        </message>
        <message>
            <source>shrink the drawing to %1 % (--scale %2)</source>
            <translation>réduire le dessin à %1 % (--scale %2)</translation>
        </message>
        <message>
            <source>move the drawing's centre to x %1 mm, y %2 mm (--at %3,%4)</source>
            <translation>déplacer le centre du dessin en x %1 mm, y %2 mm (--at %3,%4)</translation>
        </message>
        <message>
            <source>use working mode %1 (--mode %1)</source>
            <translation>utiliser le mode de travail %1 (--mode %1)</translation>
        </message>
        <message>
            <source>fit the drawing into the workspace (--fit)</source>
            <translation>ajuster le dessin à l'espace de travail (--fit)</translation>
        </message>
        <message>
            <source>job</source>
            <translation>tâche</translation>
        </message>
        <message>
            <source>working mode %1: %2: %3</source>
            <translation>mode de travail %1 : %2 : %3</translation>
        </message>
        <message>
            <source>scale must be a positive number</source>
            <translation>l'échelle doit être un nombre positif</translation>
        </message>
        <message>
            <source>nothing visible to draw in '%1'</source>
            <translation>rien de visible à dessiner dans « %1 »</translation>
        </message>
        <message>
            <source>no working mode has a singularity-free area to place the drawing in</source>
            <translation>aucun mode de travail n'a de zone sans singularité où placer le dessin</translation>
        </message>
        <message>
            <source>check the profile</source>
            <translation>vérifier le profil</translation>
        </message>
        <message>
            <source>the drawing was flattened within %1 mm, too coarse at %2 %: import it again within %3 mm</source>
            <translation>le dessin a été aplati à %1 mm près, trop grossier à %2 % : l'importer à nouveau à %3 mm près</translation>
        </message>
        <message>
            <source>move or shrink the drawing in the Placement panel</source>
            <translation>déplacer ou réduire le dessin dans le panneau Placement</translation>
        </message>
        <message>
            <source>try another working mode in the Workspace panel</source>
            <translation>essayer un autre mode de travail dans le panneau Espace de travail</translation>
        </message>
        <message>
            <source>move the drawing away from singular regions in the Placement panel</source>
            <translation>éloigner le dessin des zones singulières dans le panneau Placement</translation>
        </message>
        <message>
            <source>move the drawing away from the workspace edge in the Placement panel</source>
            <translation>éloigner le dessin du bord de l'espace de travail dans le panneau Placement</translation>
        </message>
        <message>
            <source>set Scale to %1 % in the Placement panel</source>
            <translation>régler « Échelle » sur %1 % dans le panneau Placement</translation>
        </message>
        <message>
            <source>set Centre X to %1 mm and Centre Y to %2 mm in the Placement panel</source>
            <translation>régler « Centre X » sur %1 mm et « Centre Y » sur %2 mm dans le panneau Placement</translation>
        </message>
        <message>
            <source>choose working mode %1 in the Workspace panel</source>
            <translation>choisir le mode de travail %1 dans le panneau Espace de travail</translation>
        </message>
        <message>
            <source>press Fit to workspace in the Placement panel</source>
            <translation>cliquer sur « Ajuster à l'espace » dans le panneau Placement</translation>
        </message>
    </context>
    <context>
        <name>Preflight</name>
        <message>
            <source>layer %1 path %2 point %3 at (%4, %5) mm</source>
            <translation>calque %1 chemin %2 point %3 en (%4 ; %5) mm</translation>
        </message>
        <message>
            <source>%1 is out of reach of leg %2</source>
            <translation>%1 est hors de portée du bras %2</translation>
        </message>
        <message>
            <source>%1 needs assembly mode %2 in working mode %3</source>
            <translation>%1 demande le mode d'assemblage %2 en mode de travail %3</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1 : %2</translation>
        </message>
        <message>
            <source>the line to %1 %2</source>
            <translation>la ligne vers %1 %2</translation>
        </message>
        <message>
            <source>the travel back to the home pose</source>
            <translation>le retour à la position d'origine</translation>
        </message>
        <message>
            <source>the travel to %1</source>
            <translation>le déplacement vers %1</translation>
        </message>
        <message>
            <source>%1 %2</source>
            <translation>%1 %2</translation>
        </message>
        <message>
            <source>%1; no safe detour found</source>
            <translation>%1 ; aucun détour sûr trouvé</translation>
        </message>
        <message>
            <source>%1; detour not searched (limit of searches per job reached)</source>
            <translation>%1 ; détour non cherché (limite de recherches par tâche atteinte)</translation>
        </message>
        <message>
            <source>mode %1: feasible, worst type II margin %2 deg</source>
            <translation>mode %1 : réalisable, pire marge type II %2°</translation>
        </message>
        <message>
            <source>mode %1: 1 problem</source>
            <translation>mode %1 : 1 problème</translation>
        </message>
        <message>
            <source>mode %1: %2 problems</source>
            <translation>mode %1 : %2 problèmes</translation>
        </message>
        <message>
            <source>%1 (first: %2)</source>
            <translation>%1 (premier : %2)</translation>
        </message>
        <message>
            <source>%1; fix: shrink to %2%</source>
            <translation>%1 ; solution : réduire à %2 %</translation>
        </message>
        <message>
            <source>%1; fix: move the centre to (%2, %3) mm</source>
            <translation>%1 ; solution : déplacer le centre en (%2 ; %3) mm</translation>
        </message>
        <message>
            <source>point %1 at (%2, %3) mm</source>
            <translation>point %1 en (%2 ; %3) mm</translation>
        </message>
    </context>
    <context>
        <name>QObject</name>
        <message>
            <source>Planning failed: %1</source>
            <translation>Échec de la planification : %1</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>Impossible d'écrire %1 : %2</translation>
        </message>
    </context>
    <context>
        <name>Safety</name>
        <message>
            <source>safe; closest approach to a type II singularity %1 deg</source>
            <translation>sûr ; approche la plus proche d'une singularité de type II %1°</translation>
        </message>
        <message>
            <source>passes within %1 deg of a type II singularity at (%2, %3) mm, %4% along the move</source>
            <translation>passe à moins de %1° d'une singularité de type II en (%2 ; %3) mm, à %4 % du mouvement</translation>
        </message>
        <message>
            <source>a leg comes too close to full stretch or fold (type I) at (%1, %2) mm, %3% along the move</source>
            <translation>un bras s'approche trop de l'extension ou du repli complet (type I) en (%1 ; %2) mm, à %3 % du mouvement</translation>
        </message>
        <message>
            <source>goes beyond a motor's joint limit at (%1, %2) mm, %3% along the move</source>
            <translation>dépasse la limite articulaire d'un moteur en (%1 ; %2) mm, à %3 % du mouvement</translation>
        </message>
        <message>
            <source>leaves the reachable workspace (the linkage cannot close) at (%1, %2) mm, %3% along the move</source>
            <translation>quitte l'espace de travail atteignable (le mécanisme ne peut pas se fermer) en (%1 ; %2) mm, à %3 % du mouvement</translation>
        </message>
        <message>
            <source>passes through a type II singularity, where the assembly mode can flip at (%1, %2) mm, %3% along the move</source>
            <translation>traverse une singularité de type II, où le mode d'assemblage peut basculer, en (%1 ; %2) mm, à %3 % du mouvement</translation>
        </message>
        <message>
            <source>unknown move status</source>
            <translation>état de mouvement inconnu</translation>
        </message>
    </context>
    <context>
        <name>WorkspaceLegend</name>
        <message>
            <source>type II &gt;= %1 deg, type I &gt;= %2 deg</source>
            <translation>type II &gt;= %1°, type I &gt;= %2°</translation>
        </message>
        <message>
            <source>none</source>
            <translation>aucune</translation>
        </message>
        <message>
            <source>singularity-free (%1)</source>
            <translation>sans singularité (%1)</translation>
        </message>
        <message>
            <source>reachable, within a singularity margin</source>
            <translation>atteignable, dans une marge de singularité</translation>
        </message>
        <message>
            <source>reach boundary</source>
            <translation>limite d'atteinte</translation>
        </message>
        <message>
            <source>singularity-free boundary</source>
            <translation>limite de la zone sans singularité</translation>
        </message>
        <message>
            <source>type II singularity (%1 curves)</source>
            <translation>singularité de type II (%1 courbes)</translation>
        </message>
        <message>
            <source>largest rectangle: %1</source>
            <translation>plus grand rectangle : %1</translation>
        </message>
        <message>
            <source>reachable area: %1 cm²</source>
            <translation>surface atteignable : %1 cm²</translation>
        </message>
        <message>
            <source>singularity-free area: %1 cm²</source>
            <translation>surface sans singularité : %1 cm²</translation>
        </message>
    </context>
    <context>
        <name>fivebar::studio::FileActions</name>
        <message>
            <source>Unsaved changes</source>
            <translation>Modifications non enregistrées</translation>
        </message>
        <message>
            <source>%1 has changes that are not saved. Save them first?</source>
            <translation>%1 contient des modifications non enregistrées. Les enregistrer d'abord ?</translation>
        </message>
        <message>
            <source>Cannot save %1: %2</source>
            <translation>Impossible d'enregistrer %1 : %2</translation>
        </message>
        <message>
            <source>Nothing to save: open a drawing first.</source>
            <translation>Rien à enregistrer : ouvrez d'abord un dessin.</translation>
        </message>
        <message>
            <source>Save failed</source>
            <translation>Échec de l'enregistrement</translation>
        </message>
        <message>
            <source>Saved %1</source>
            <translation>%1 enregistré</translation>
        </message>
        <message>
            <source>Save project</source>
            <translation>Enregistrer le projet</translation>
        </message>
        <message>
            <source>FiveBar projects (*.fivebar)</source>
            <translation>Projets FiveBar (*.fivebar)</translation>
        </message>
        <message>
            <source>The job is still being planned; export it when planning is done.</source>
            <translation>La tâche est encore en cours de planification ; exportez-la une fois la planification terminée.</translation>
        </message>
        <message>
            <source>There is no planned job to export (see the job preview).</source>
            <translation>Il n'y a aucune tâche planifiée à exporter (voir l'aperçu de la tâche).</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>Impossible d'écrire %1 : %2</translation>
        </message>
        <message>
            <source>Export G-code</source>
            <translation>Exporter le G-code</translation>
        </message>
        <message>
            <source>G-code (*.gcode *.nc);;All files (*)</source>
            <translation>G-code (*.gcode *.nc);;Tous les fichiers (*)</translation>
        </message>
        <message>
            <source>Exported %1</source>
            <translation>%1 exporté</translation>
        </message>
        <message>
            <source>Clear list</source>
            <translation>Vider la liste</translation>
        </message>
        <message>
            <source>The untitled project made from %1 has changes that are not saved. Save it as a project first?</source>
            <translation>Le projet sans titre créé à partir de %1 contient des modifications non enregistrées. L'enregistrer d'abord comme projet ?</translation>
        </message>
    </context>
    <context>
        <name>fivebar::studio::LanguageMenu</name>
        <message>
            <source>&amp;Language</source>
            <translation>&amp;Langue</translation>
        </message>
        <message>
            <source>System default</source>
            <translation>Langue du système</translation>
        </message>
        <message>
            <source>Language</source>
            <translation>Langue</translation>
        </message>
        <message>
            <source>The new language applies when FiveBar Studio starts again.</source>
            <translation>La nouvelle langue s'applique au prochain démarrage de FiveBar Studio.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::studio::MainWindow</name>
        <message>
            <source>FiveBar Studio</source>
            <translation>FiveBar Studio</translation>
        </message>
        <message>
            <source>x %1 mm, y %2 mm</source>
            <translation>x %1 mm, y %2 mm</translation>
        </message>
        <message>
            <source>Planning...</source>
            <translation>Planification…</translation>
        </message>
        <message>
            <source>Workspace</source>
            <translation>Espace de travail</translation>
        </message>
        <message>
            <source>Placement</source>
            <translation>Placement</translation>
        </message>
        <message>
            <source>Layers</source>
            <translation>Calques</translation>
        </message>
        <message>
            <source>Job preview</source>
            <translation>Aperçu de la tâche</translation>
        </message>
        <message>
            <source>Simulation</source>
            <translation>Simulation</translation>
        </message>
        <message>
            <source>&amp;File</source>
            <translation>&amp;Fichier</translation>
        </message>
        <message>
            <source>Open &amp;recent</source>
            <translation>Ouvrir un fichier &amp;récent</translation>
        </message>
        <message>
            <source>&amp;Quit</source>
            <translation>&amp;Quitter</translation>
        </message>
        <message>
            <source>&amp;Edit</source>
            <translation>&amp;Édition</translation>
        </message>
        <message>
            <source>&amp;Undo</source>
            <translation>&amp;Annuler</translation>
        </message>
        <message>
            <source>&amp;Redo</source>
            <translation>&amp;Rétablir</translation>
        </message>
        <message>
            <source>&amp;Fit drawing to workspace</source>
            <translation>&amp;Ajuster le dessin à l'espace de travail</translation>
        </message>
        <message>
            <source>Ctrl+F</source>
            <translation>Ctrl+F</translation>
        </message>
        <message>
            <source>&amp;View</source>
            <translation>Affic&amp;hage</translation>
        </message>
        <message>
            <source>Zoom &amp;in</source>
            <translation>Zoom a&amp;vant</translation>
        </message>
        <message>
            <source>Ctrl+=</source>
            <translation>Ctrl+=</translation>
        </message>
        <message>
            <source>Zoom &amp;out</source>
            <translation>Zoom a&amp;rrière</translation>
        </message>
        <message>
            <source>Zoom to &amp;fit</source>
            <translation>Zoom &amp;ajusté</translation>
        </message>
        <message>
            <source>Ctrl+0</source>
            <translation>Ctrl+0</translation>
        </message>
        <message>
            <source>&amp;Simulation</source>
            <translation>&amp;Simulation</translation>
        </message>
        <message>
            <source>&amp;Play / pause</source>
            <translation>&amp;Lecture / pause</translation>
        </message>
        <message>
            <source>F5</source>
            <translation>F5</translation>
        </message>
        <message>
            <source>Step &amp;forward</source>
            <translation>Pas en a&amp;vant</translation>
        </message>
        <message>
            <source>F6</source>
            <translation>F6</translation>
        </message>
        <message>
            <source>Step &amp;back</source>
            <translation>Pas en a&amp;rrière</translation>
        </message>
        <message>
            <source>Shift+F6</source>
            <translation>Shift+F6</translation>
        </message>
        <message>
            <source>&amp;Machine</source>
            <translation>&amp;Machine</translation>
        </message>
        <message>
            <source>&amp;Help</source>
            <translation>Ai&amp;de</translation>
        </message>
        <message>
            <source>&amp;About FiveBar Studio</source>
            <translation>&amp;À propos de FiveBar Studio</translation>
        </message>
        <message>
            <source>About FiveBar Studio</source>
            <translation>À propos de FiveBar Studio</translation>
        </message>
        <message>
            <source>&lt;b&gt;FiveBar Studio %1&lt;/b&gt;&lt;p&gt;Plans and simulates drawings for five-bar linkage robots: workspace and singularity analysis, safe job planning, GRBL output.&lt;/p&gt;</source>
            <translation>&lt;b&gt;FiveBar Studio %1&lt;/b&gt;&lt;p&gt;Planifie et simule des dessins pour robots à cinq barres : analyse de l'espace de travail et des singularités, planification sûre des tâches, sortie GRBL.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Main</source>
            <translation>Principale</translation>
        </message>
        <message>
            <source>&amp;Open drawing or project...</source>
            <translation>&amp;Ouvrir un dessin ou un projet…</translation>
        </message>
        <message>
            <source>&amp;Save project</source>
            <translation>&amp;Enregistrer le projet</translation>
        </message>
        <message>
            <source>Save project &amp;as...</source>
            <translation>Enregistrer le projet &amp;sous…</translation>
        </message>
        <message>
            <source>&amp;Export G-code...</source>
            <translation>E&amp;xporter le G-code…</translation>
        </message>
        <message>
            <source>Ctrl+E</source>
            <translation>Ctrl+E</translation>
        </message>
        <message>
            <source>&amp;Actual size (100 %)</source>
            <translation>&amp;Taille réelle (100 %)</translation>
        </message>
        <message>
            <source>Ctrl+1</source>
            <translation>Ctrl+1</translation>
        </message>
        <message>
            <source>%1[*] - FiveBar Studio</source>
            <translation>%1[*] - FiveBar Studio</translation>
        </message>
        <message>
            <source>Fills</source>
            <translation>Remplissage</translation>
        </message>
        <message>
            <source>Import warnings</source>
            <translation>Avertissements d'import</translation>
        </message>
        <message>
            <source>Untitled project (%1)[*] - FiveBar Studio</source>
            <translation>Projet sans titre (%1)[*] - FiveBar Studio</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ConsolePanel</name>
        <message>
            <source>Lines sent to and received from the machine appear here.</source>
            <translation>Les lignes envoyées à la machine et reçues d'elle apparaissent ici.</translation>
        </message>
        <message>
            <source>Send</source>
            <translation>Envoyer</translation>
        </message>
        <message>
            <source>G-code or $ command, e.g. $$ or $I; moves are checked first</source>
            <translation>G-code ou commande $, p. ex. $$ ou $I ; les déplacements sont d'abord vérifiés</translation>
        </message>
        <message>
            <source>Send unchecked (expert)</source>
            <translation>Envoyer sans vérification (expert)</translation>
        </message>
        <message>
            <source>Send lines without the motion check. X and Y are motor angles in degrees: a wrong number swings an arm across the base.</source>
            <translation>Envoyer les lignes sans vérification du mouvement. X et Y sont des angles moteur en degrés : une valeur erronée fait balayer un bras à travers la base.</translation>
        </message>
        <message>
            <source>Unchecked console: lines go to the machine as typed, without the motion check. A wrong X or Y (motor angles in degrees) can drive the arms into each other or the base.</source>
            <translation>Console non vérifiée : les lignes partent vers la machine telles que saisies, sans vérification du mouvement. Un X ou Y erroné (angles moteur en degrés) peut faire heurter les bras entre eux ou contre la base.</translation>
        </message>
        <message>
            <source>Not sent: %1</source>
            <translation>Non envoyé : %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::DesignDialog</name>
        <message>
            <source>Design a machine</source>
            <translation>Concevoir une machine</translation>
        </message>
        <message>
            <source>&amp;Design...</source>
            <translation>&amp;Conception…</translation>
        </message>
        <message>
            <source>Choose link lengths for a paper size</source>
            <translation>Choisir les longueurs des bras pour un format de papier</translation>
        </message>
        <message>
            <source>Brief</source>
            <translation>Cahier des charges</translation>
        </message>
        <message>
            <source>Custom</source>
            <translation>Personnalisé</translation>
        </message>
        <message>
            <source>Landscape</source>
            <translation>Paysage</translation>
        </message>
        <message>
            <source>Portrait</source>
            <translation>Portrait</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> deg</source>
            <translation> °</translation>
        </message>
        <message>
            <source>Symmetric arms</source>
            <translation>Bras symétriques</translation>
        </message>
        <message>
            <source>Any</source>
            <translation>Tous</translation>
        </message>
        <message>
            <source>Worst condition number</source>
            <translation>Pire conditionnement</translation>
        </message>
        <message>
            <source>Worst resolution</source>
            <translation>Pire résolution</translation>
        </message>
        <message>
            <source>Footprint</source>
            <translation>Encombrement</translation>
        </message>
        <message>
            <source>Weighted mix</source>
            <translation>Mélange pondéré</translation>
        </message>
        <message>
            <source>Condition</source>
            <translation>Conditionnement</translation>
        </message>
        <message>
            <source>Resolution</source>
            <translation>Résolution</translation>
        </message>
        <message>
            <source>Weight of this normalised term in the weighted mix</source>
            <translation>Poids de ce terme normalisé dans le mélange pondéré</translation>
        </message>
        <message>
            <source>Mix weights</source>
            <translation>Poids du mélange</translation>
        </message>
        <message>
            <source>Paper</source>
            <translation>Papier</translation>
        </message>
        <message>
            <source>Orientation</source>
            <translation>Orientation</translation>
        </message>
        <message>
            <source>Width</source>
            <translation>Largeur</translation>
        </message>
        <message>
            <source>Height</source>
            <translation>Hauteur</translation>
        </message>
        <message>
            <source>Margin</source>
            <translation>Marge</translation>
        </message>
        <message>
            <source>Shortest link</source>
            <translation>Bras le plus court</translation>
        </message>
        <message>
            <source>Longest link</source>
            <translation>Bras le plus long</translation>
        </message>
        <message>
            <source>Smallest motor spacing</source>
            <translation>Plus petit entraxe</translation>
        </message>
        <message>
            <source>Largest motor spacing</source>
            <translation>Plus grand entraxe</translation>
        </message>
        <message>
            <source>Arm clearance</source>
            <translation>Dégagement des bras</translation>
        </message>
        <message>
            <source>Type II margin</source>
            <translation>Marge type II</translation>
        </message>
        <message>
            <source>Working mode</source>
            <translation>Mode de travail</translation>
        </message>
        <message>
            <source>Objective</source>
            <translation>Objectif</translation>
        </message>
        <message>
            <source>Search</source>
            <translation>Chercher</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Annuler</translation>
        </message>
        <message>
            <source>Set the brief and press Search.</source>
            <translation>Réglez le cahier des charges et appuyez sur Chercher.</translation>
        </message>
        <message>
            <source>Worst condition</source>
            <translation>Pire conditionnement</translation>
        </message>
        <message>
            <source>Footprint (cm²)</source>
            <translation>Encombrement (cm²)</translation>
        </message>
        <message>
            <source>µm/step</source>
            <translation>µm/pas</translation>
        </message>
        <message>
            <source>Mode</source>
            <translation>Mode</translation>
        </message>
        <message>
            <source>Workspace</source>
            <translation>Espace de travail</translation>
        </message>
        <message>
            <source>Conditioning</source>
            <translation>Conditionnement</translation>
        </message>
        <message>
            <source>Transmission angle</source>
            <translation>Angle de transmission</translation>
        </message>
        <message>
            <source>Map on the canvas</source>
            <translation>Carte sur le canevas</translation>
        </message>
        <message>
            <source>Use as profile</source>
            <translation>Utiliser comme profil</translation>
        </message>
        <message>
            <source>Export...</source>
            <translation>Exporter…</translation>
        </message>
        <message>
            <source>Searching...</source>
            <translation>Recherche…</translation>
        </message>
        <message>
            <source>Search cancelled.</source>
            <translation>Recherche annulée.</translation>
        </message>
        <message>
            <source>No design meets the brief: %1</source>
            <translation>Aucune conception ne respecte le cahier des charges : %1</translation>
        </message>
        <message>
            <source>Best worst-case condition number %1; %2 designs on the trade-off, %3 evaluations in %4 s.</source>
            <translation>Meilleur conditionnement au pire cas %1 ; %2 conceptions sur le compromis, %3 évaluations en %4 s.</translation>
        </message>
        <message>
            <source>The document now uses this design (Edit &gt; Undo restores the previous profile).</source>
            <translation>Le document utilise maintenant cette conception (Édition &gt; Annuler rétablit le profil précédent).</translation>
        </message>
        <message>
            <source>No design is selected.</source>
            <translation>Aucune conception sélectionnée.</translation>
        </message>
        <message>
            <source>Export profile</source>
            <translation>Exporter le profil</translation>
        </message>
        <message>
            <source>Machine profiles (*.json)</source>
            <translation>Profils de machine (*.json)</translation>
        </message>
        <message>
            <source>Profile written to %1.</source>
            <translation>Profil écrit dans %1.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::FillOptionsBox</name>
        <message>
            <source>Draw dashed strokes solid</source>
            <translation>Dessiner les traits pointillés en continu</translation>
        </message>
        <message>
            <source>Dashed strokes are drawn as their dashes, the pen lifted between them; checked: each dashed stroke is drawn as one line.</source>
            <translation>Les traits pointillés sont dessinés tiret par tiret, le stylo levé entre les tirets ; coché : chaque trait pointillé est dessiné d’un seul trait.</translation>
        </message>
        <message>
            <source>Filled shapes</source>
            <translation>Formes remplies</translation>
        </message>
        <message>
            <source>Outline</source>
            <translation>Contour</translation>
        </message>
        <message>
            <source>Hatch</source>
            <translation>Hachures</translation>
        </message>
        <message>
            <source>Not drawn</source>
            <translation>Non tracées</translation>
        </message>
        <message>
            <source>Outline: the shape's edge (as AxiDraw and vpype draw fills). Hatch: parallel lines inside the shape. Not drawn: fill-only shapes are left out.</source>
            <translation>Contour : le bord de la forme (comme AxiDraw et vpype tracent les remplissages). Hachures : des lignes parallèles dans la forme. Non tracées : les formes seulement remplies sont omises.</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> deg</source>
            <translation> °</translation>
        </message>
        <message>
            <source>Crosshatch</source>
            <translation>Hachures croisées</translation>
        </message>
        <message>
            <source>Keep the outline</source>
            <translation>Garder le contour</translation>
        </message>
        <message>
            <source>Import again with these settings</source>
            <translation>Réimporter avec ces réglages</translation>
        </message>
        <message>
            <source>Fill:</source>
            <translation>Remplissage :</translation>
        </message>
        <message>
            <source>Line spacing:</source>
            <translation>Espacement :</translation>
        </message>
        <message>
            <source>Angle:</source>
            <translation>Angle :</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::GoToTool</name>
        <message>
            <source>Connect the machine first: its position is not known.</source>
            <translation>Connectez d'abord la machine : sa position est inconnue.</translation>
        </message>
        <message>
            <source>Cannot go there: %1</source>
            <translation>Impossible d'y aller : %1</translation>
        </message>
        <message numerus="yes">
            <source>Go to %1, %2 mm? The dashed path is the pen's travel (%n checked move(s)).</source>
            <translation>
                <numerusform>Aller à %1, %2 mm ? Le tracé en pointillés est le trajet du stylo (%n mouvement vérifié).</numerusform>
                <numerusform>Aller à %1, %2 mm ? Le tracé en pointillés est le trajet du stylo (%n mouvements vérifiés).</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ImportController</name>
        <message>
            <source>%1: another import is still running.</source>
            <translation>%1 : un autre import est encore en cours.</translation>
        </message>
        <message>
            <source>Importing %1...</source>
            <translation>Import de %1…</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Annuler</translation>
        </message>
        <message>
            <source>Import</source>
            <translation>Import</translation>
        </message>
        <message>
            <source>Import of %1 cancelled.</source>
            <translation>Import de %1 annulé.</translation>
        </message>
        <message>
            <source>%1 could not be imported.</source>
            <translation>%1 n'a pas pu être importé.</translation>
        </message>
        <message>
            <source>Import failed</source>
            <translation>Échec de l'import</translation>
        </message>
        <message>
            <source>%1 contains nothing to draw.</source>
            <translation>%1 ne contient rien à tracer.</translation>
        </message>
        <message>
            <source>Open drawing or project</source>
            <translation>Ouvrir un dessin ou un projet</translation>
        </message>
        <message>
            <source>Drawings and projects (*.svg *.fivebar);;SVG drawings (*.svg);;FiveBar projects (*.fivebar);;All files (*)</source>
            <translation>Dessins et projets (*.svg *.fivebar);;Dessins SVG (*.svg);;Projets FiveBar (*.fivebar);;Tous les fichiers (*)</translation>
        </message>
        <message>
            <source>Very large drawing</source>
            <translation>Dessin très volumineux</translation>
        </message>
        <message>
            <source>%1 has more than %2 points after flattening (a runaway file?). Reading it was stopped there.

Planning and plotting it may take very long. Import it whole anyway?</source>
            <translation>%1 compte plus de %2 points après aplatissement (fichier aberrant ?). La lecture s'est arrêtée là.

La planification et le traçage peuvent être très longs. L'importer quand même en entier ?</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ImportWarningsPanel</name>
        <message>
            <source>No drawing imported yet.</source>
            <translation>Aucun dessin importé pour l'instant.</translation>
        </message>
        <message>
            <source>What the importer dropped, approximated or could not draw. docs/svg-import.md lists what is supported.</source>
            <translation>Ce que l'import a omis, approché ou n'a pas pu tracer. docs/svg-import.md liste ce qui est pris en charge.</translation>
        </message>
        <message>
            <source>%1 imported without warnings.</source>
            <translation>%1 importé sans avertissement.</translation>
        </message>
        <message>
            <source>1 warning while importing %1: part of the drawing may differ from what a browser shows.</source>
            <translation>1 avertissement à l'import de %1 : une partie du dessin peut différer de ce qu'affiche un navigateur.</translation>
        </message>
        <message>
            <source>%1 warnings while importing %2: parts of the drawing may differ from what a browser shows.</source>
            <translation>%1 avertissements à l'import de %2 : des parties du dessin peuvent différer de ce qu'affiche un navigateur.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::JobLayer</name>
        <message>
            <source>Planning...</source>
            <translation>Planification…</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::JogController</name>
        <message>
            <source>Jog refused: the machine is not connected, not idle, or a job is running.</source>
            <translation>Déplacement refusé : la machine n'est pas connectée, pas au repos, ou une tâche est en cours.</translation>
        </message>
        <message>
            <source>Jog stopped at the last safe point: %1</source>
            <translation>Déplacement arrêté au dernier point sûr : %1</translation>
        </message>
        <message>
            <source>Jog refused: %1</source>
            <translation>Déplacement refusé : %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::JogPanel</name>
        <message>
            <source>Frame the job</source>
            <translation>Cadrer le travail</translation>
        </message>
        <message>
            <source>Trace the outline of the planned job with the pen up (a laser at low power), along checked moves, to see where the drawing lands on the paper</source>
            <translation>Parcourir le contour du travail planifié stylo levé (un laser à faible puissance), par des mouvements vérifiés, pour voir où le dessin tombe sur le papier</translation>
        </message>
        <message>
            <source>Tracing the job's outline with the pen up.</source>
            <translation>Parcours du contour du travail, stylo levé.</translation>
        </message>
        <message>
            <source>Jog the pen %1 mm in X, %2 mm in Y per step; hold for a continuous jog</source>
            <translation>Déplacer le stylo de %1 mm en X et %2 mm en Y par pas ; maintenir pour un déplacement continu</translation>
        </message>
        <message>
            <source>Go to…</source>
            <translation>Aller à…</translation>
        </message>
        <message>
            <source>Click the canvas to choose where the pen goes; the path is shown before you confirm.</source>
            <translation>Cliquez sur le canevas pour choisir où va le stylo ; le trajet est affiché avant de confirmer.</translation>
        </message>
        <message>
            <source>Turn motor %1 clockwise by one step</source>
            <translation>Tourner le moteur %1 d'un pas dans le sens horaire</translation>
        </message>
        <message>
            <source>Turn motor %1 counter-clockwise by one step</source>
            <translation>Tourner le moteur %1 d'un pas dans le sens antihoraire</translation>
        </message>
        <message>
            <source>Step</source>
            <translation>Pas</translation>
        </message>
        <message>
            <source>mm / °</source>
            <translation>mm / °</translation>
        </message>
        <message>
            <source> mm/s</source>
            <translation> mm/s</translation>
        </message>
        <message>
            <source>Pen up</source>
            <translation>Lever le stylo</translation>
        </message>
        <message>
            <source>Lift the pen (Page Up on the canvas)</source>
            <translation>Lever le stylo (Page précédente sur le canevas)</translation>
        </message>
        <message>
            <source>Pen down</source>
            <translation>Baisser le stylo</translation>
        </message>
        <message>
            <source>Lower the pen (Page Down on the canvas)</source>
            <translation>Baisser le stylo (Page suivante sur le canevas)</translation>
        </message>
        <message>
            <source>Go</source>
            <translation>Aller</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Annuler</translation>
        </message>
        <message>
            <source>Click the canvas where the pen should go.</source>
            <translation>Cliquez sur le canevas là où le stylo doit aller.</translation>
        </message>
        <message>
            <source>Home ($H)</source>
            <translation>Origine ($H)</translation>
        </message>
        <message>
            <source>Set reference pose</source>
            <translation>Définir la pose de référence</translation>
        </message>
        <message>
            <source>Run the homing cycle</source>
            <translation>Lancer la prise d'origine</translation>
        </message>
        <message>
            <source>Declare that the machine now stands at the profile's home pose</source>
            <translation>Déclarer que la machine est maintenant dans la pose d'origine du profil</translation>
        </message>
        <message>
            <source>Speed of XY jogs</source>
            <translation>Vitesse des déplacements XY</translation>
        </message>
        <message>
            <source>Go to home pose</source>
            <translation>Aller à la position d'origine</translation>
        </message>
        <message>
            <source>Move the pen up to the profile's home pose by a checked move (the reference must be set)</source>
            <translation>Amener le stylo relevé à la position d'origine du profil par un déplacement vérifié (la référence doit être définie)</translation>
        </message>
        <message>
            <source>Speed</source>
            <translation>Vitesse</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::LayersPanel</name>
        <message>
            <source>Plot this layer earlier</source>
            <translation>Tracer ce calque plus tôt</translation>
        </message>
        <message>
            <source>Plot this layer later</source>
            <translation>Tracer ce calque plus tard</translation>
        </message>
        <message>
            <source>Tool settings of the selected layer</source>
            <translation>Réglages d'outil du calque sélectionné</translation>
        </message>
        <message>
            <source> mm/s</source>
            <translation> mm/s</translation>
        </message>
        <message>
            <source>Profile default</source>
            <translation>Valeur du profil</translation>
        </message>
        <message>
            <source>Pause before this layer (pen change)</source>
            <translation>Pause avant ce calque (changement de stylo)</translation>
        </message>
        <message>
            <source>Draw speed:</source>
            <translation>Vitesse de tracé :</translation>
        </message>
        <message>
            <source>Power / pen S:</source>
            <translation>Puissance / S stylo :</translation>
        </message>
        <message numerus="yes">
            <source>%n path(s)</source>
            <translation>
                <numerusform>%n tracé</numerusform>
                <numerusform>%n tracés</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n point(s)</source>
            <translation>
                <numerusform>%n point</numerusform>
                <numerusform>%n points</numerusform>
            </translation>
        </message>
        <message>
            <source>Fill of the selected layer</source>
            <translation>Remplissage du calque sélectionné</translation>
        </message>
        <message>
            <source>Outline</source>
            <translation>Contour</translation>
        </message>
        <message>
            <source>Hatch</source>
            <translation>Hachures</translation>
        </message>
        <message>
            <source>None</source>
            <translation>Aucun</translation>
        </message>
        <message>
            <source>How the layer's filled shapes are drawn: their outline, parallel hatch lines inside them, or not at all (stroked shapes keep their stroke).</source>
            <translation>Comment les formes remplies du calque sont tracées : leur contour, des hachures parallèles à l'intérieur, ou pas du tout (les formes à trait gardent leur trait).</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> °</source>
            <translation> °</translation>
        </message>
        <message>
            <source>Crosshatch</source>
            <translation>Hachures croisées</translation>
        </message>
        <message>
            <source>Fill:</source>
            <translation>Remplissage :</translation>
        </message>
        <message>
            <source>Hatch spacing:</source>
            <translation>Espacement des hachures :</translation>
        </message>
        <message>
            <source>Hatch angle:</source>
            <translation>Angle des hachures :</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachineBanner</name>
        <message>
            <source>Reset</source>
            <translation>Réinitialiser</translation>
        </message>
        <message>
            <source>Soft reset (Ctrl-X): stops everything; the machine keeps its position unless it was moving.</source>
            <translation>Réinitialisation logicielle (Ctrl-X) : arrête tout ; la machine garde sa position sauf si elle bougeait.</translation>
        </message>
        <message>
            <source>Unlock ($X)</source>
            <translation>Déverrouiller ($X)</translation>
        </message>
        <message>
            <source>Leave the alarm state without homing. Only when you know the machine stands where the studio shows it.</source>
            <translation>Quitter l'état d'alarme sans prise d'origine. Seulement si vous savez que la machine est là où le studio l'affiche.</translation>
        </message>
        <message>
            <source>Dismiss</source>
            <translation>Fermer</translation>
        </message>
        <message>
            <source>Alarm %1: the machine stopped</source>
            <translation>Alarme %1 : la machine s'est arrêtée</translation>
        </message>
        <message>
            <source>Alarm: the machine is locked</source>
            <translation>Alarme : la machine est verrouillée</translation>
        </message>
        <message>
            <source>Error %1: a command was rejected</source>
            <translation>Erreur %1 : une commande a été refusée</translation>
        </message>
        <message>
            <source>The board waits for a reset first: press Reset, then Unlock.</source>
            <translation>La carte attend d'abord une réinitialisation : appuyez sur Réinitialiser, puis Déverrouiller.</translation>
        </message>
        <message>
            <source>Home ($H)</source>
            <translation>Origine ($H)</translation>
        </message>
        <message>
            <source>Set reference pose</source>
            <translation>Définir la pose de référence</translation>
        </message>
        <message>
            <source>Run the homing cycle; the machine moves to its switches.</source>
            <translation>Lancer la prise d'origine ; la machine va jusqu'à ses capteurs.</translation>
        </message>
        <message>
            <source>Declare that the machine now stands at the profile's home pose (G10 L20).</source>
            <translation>Déclarer que la machine est maintenant dans la pose d'origine du profil (G10 L20).</translation>
        </message>
        <message>
            <source>Position unknown: nothing moves until it is set</source>
            <translation>Position inconnue : rien ne bouge tant qu'elle n'est pas définie</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachineDialogs</name>
        <message>
            <source>Set the reference pose?

The studio will take the machine's current position to be the home pose of "%1": motor 1 at %2°, motor 2 at %3°. Every later move is computed from it.

Confirm only if the arms stand exactly in that pose now. If they stand elsewhere, moves will land in the wrong place and can drive the arms into each other or into the base.</source>
            <translation>Définir la pose de référence ?

Le studio va considérer la position actuelle de la machine comme la position d'origine de « %1 » : moteur 1 à %2°, moteur 2 à %3°. Tous les déplacements suivants sont calculés à partir d'elle.

Confirmez seulement si les bras sont exactement dans cette pose. S'ils sont ailleurs, les déplacements arriveront au mauvais endroit et peuvent faire heurter les bras entre eux ou contre la base.</translation>
        </message>
        <message>
            <source>Set reference pose</source>
            <translation>Définir la pose de référence</translation>
        </message>
        <message>
            <source>The arms stand in the home pose: set it</source>
            <translation>Les bras sont en position d'origine : la définir</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Annuler</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachinePanel</name>
        <message>
            <source>Idle</source>
            <translation>Au repos</translation>
        </message>
        <message>
            <source>Running</source>
            <translation>En marche</translation>
        </message>
        <message>
            <source>On hold</source>
            <translation>En pause</translation>
        </message>
        <message>
            <source>Jogging</source>
            <translation>Déplacement</translation>
        </message>
        <message>
            <source>Alarm</source>
            <translation>Alarme</translation>
        </message>
        <message>
            <source>Door open</source>
            <translation>Porte ouverte</translation>
        </message>
        <message>
            <source>Check mode</source>
            <translation>Mode test</translation>
        </message>
        <message>
            <source>Homing</source>
            <translation>Prise d'origine</translation>
        </message>
        <message>
            <source>Sleeping</source>
            <translation>En veille</translation>
        </message>
        <message>
            <source>Unknown</source>
            <translation>Inconnu</translation>
        </message>
        <message>
            <source>Refresh</source>
            <translation>Actualiser</translation>
        </message>
        <message>
            <source>List the serial ports again</source>
            <translation>Lister à nouveau les ports série</translation>
        </message>
        <message>
            <source>Connect</source>
            <translation>Connecter</translation>
        </message>
        <message>
            <source>Disconnect</source>
            <translation>Déconnecter</translation>
        </message>
        <message>
            <source>Baud</source>
            <translation>Baud</translation>
        </message>
        <message>
            <source>Connection</source>
            <translation>Connexion</translation>
        </message>
        <message>
            <source>Status</source>
            <translation>État</translation>
        </message>
        <message>
            <source>State</source>
            <translation>État</translation>
        </message>
        <message>
            <source>Pen (X, Y)</source>
            <translation>Stylo (X, Y)</translation>
        </message>
        <message>
            <source>Motors (θ1, θ2)</source>
            <translation>Moteurs (θ1, θ2)</translation>
        </message>
        <message>
            <source>Buffers</source>
            <translation>Tampons</translation>
        </message>
        <message>
            <source>Simulated machine (built in)</source>
            <translation>Machine simulée (intégrée)</translation>
        </message>
        <message>
            <source>Cannot connect</source>
            <translation>Connexion impossible</translation>
        </message>
        <message>
            <source>Connected to %1</source>
            <translation>Connecté à %1</translation>
        </message>
        <message>
            <source>Not connected</source>
            <translation>Non connecté</translation>
        </message>
        <message>
            <source>Offline</source>
            <translation>Hors ligne</translation>
        </message>
        <message>
            <source>%1, %2 mm</source>
            <translation>%1, %2 mm</translation>
        </message>
        <message>
            <source>%1°, %2°</source>
            <translation>%1°, %2°</translation>
        </message>
        <message>
            <source>planner %1 of %2 blocks free, RX %3 of %4 bytes free</source>
            <translation>planificateur : %1 blocs libres sur %2, RX : %3 octets libres sur %4</translation>
        </message>
        <message>
            <source>Pen</source>
            <translation>Stylo</translation>
        </message>
        <message>
            <source>Review and write...</source>
            <translation>Vérifier et écrire...</translation>
        </message>
        <message>
            <source>Compare the board's settings with the profile and write the differences (a backup is saved first)</source>
            <translation>Comparer les réglages de la carte avec le profil et écrire les différences (une sauvegarde est faite d'abord)</translation>
        </message>
        <message>
            <source>No answer from the machine</source>
            <translation>Aucune réponse de la machine</translation>
        </message>
        <message>
            <source>Connecting to %1: waiting for the board to answer...</source>
            <translation>Connexion à %1 : attente de la réponse de la carte...</translation>
        </message>
        <message>
            <source>up</source>
            <translation>levé</translation>
        </message>
        <message>
            <source>down (drawing)</source>
            <translation>baissé (tracé)</translation>
        </message>
        <message>
            <source>not known yet</source>
            <translation>pas encore connu</translation>
        </message>
        <message>
            <source>unknown (set the reference pose)</source>
            <translation>inconnue (définissez la pose de référence)</translation>
        </message>
        <message>
            <source>Cannot open %1.</source>
            <translation>Impossible d'ouvrir %1.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::MachineSession</name>
        <message>
            <source>No job is planned: open a drawing and let it plan first.</source>
            <translation>Aucun travail n'est planifié : ouvrez d'abord un dessin et laissez-le se planifier.</translation>
        </message>
        <message>
            <source>No checked frame of the job: %1</source>
            <translation>Aucun cadrage vérifié du travail : %1</translation>
        </message>
        <message>
            <source>The frame was not sent (see the console).</source>
            <translation>Le cadrage n'a pas été envoyé (voir la console).</translation>
        </message>
        <message>
            <source>Frame: the job's outline, %1 mm, pen up</source>
            <translation>Cadrage : le contour du travail, %1 mm, stylo levé</translation>
        </message>
        <message>
            <source>Cannot open %1.</source>
            <translation>Impossible d'ouvrir %1.</translation>
        </message>
        <message>
            <source>Connected to %1.</source>
            <translation>Connecté à %1.</translation>
        </message>
        <message>
            <source>Disconnected.</source>
            <translation>Déconnecté.</translation>
        </message>
        <message>
            <source>Not connected: %1 was not sent.</source>
            <translation>Non connecté : %1 n'a pas été envoyé.</translation>
        </message>
        <message>
            <source>Not sent (%1): %2</source>
            <translation>Non envoyé (%1) : %2</translation>
        </message>
        <message>
            <source>A job is running: %1 was not sent.</source>
            <translation>Une tâche est en cours : %1 n'a pas été envoyé.</translation>
        </message>
        <message>
            <source>Jog refused: the machine is not idle, not connected or a job is running.</source>
            <translation>Déplacement refusé : la machine n'est pas au repos, pas connectée, ou une tâche est en cours.</translation>
        </message>
        <message>
            <source>[soft reset]</source>
            <translation>[réinitialisation logicielle]</translation>
        </message>
        <message>
            <source>[feed hold]</source>
            <translation>[pause d'avance]</translation>
        </message>
        <message>
            <source>[cycle start]</source>
            <translation>[départ cycle]</translation>
        </message>
        <message>
            <source>%1 was rejected: %2</source>
            <translation>%1 a été refusé : %2</translation>
        </message>
        <message>
            <source>The machine is locked (alarm state). Unlock it with $X or home it with $H once you know where it stands.</source>
            <translation>La machine est verrouillée (état d'alarme). Déverrouillez-la avec $X ou faites sa prise d'origine avec $H une fois que vous savez où elle se trouve.</translation>
        </message>
        <message>
            <source>The board reset (Grbl %1).</source>
            <translation>La carte a été réinitialisée (Grbl %1).</translation>
        </message>
        <message>
            <source>Connection lost: %1</source>
            <translation>Connexion perdue : %1</translation>
        </message>
        <message>
            <source>the simulated machine</source>
            <translation>la machine simulée</translation>
        </message>
        <message>
            <source>set the reference pose (Machine panel) or home the machine</source>
            <translation>définissez la pose de référence (panneau Machine) ou lancez le homing de la machine</translation>
        </message>
        <message>
            <source>%1 at %2 baud</source>
            <translation>%1 à %2 bauds</translation>
        </message>
        <message>
            <source>Opened %1; waiting for the board to answer...</source>
            <translation>%1 ouvert ; attente de la réponse de la carte...</translation>
        </message>
        <message>
            <source>No GRBL board answered on %1 within %2 s. Check that the port is the machine's, that the baud rate matches its firmware (GRBL 1.1: usually 115200) and that it is powered.</source>
            <translation>Aucune carte GRBL n'a répondu sur %1 en %2 s. Vérifiez que le port est celui de la machine, que le débit correspond à son firmware (GRBL 1.1 : souvent 115200) et qu'elle est alimentée.</translation>
        </message>
        <message>
            <source>Not sent: %1</source>
            <translation>Non envoyé : %1</translation>
        </message>
        <message>
            <source>Unchecked: %1</source>
            <translation>Non vérifié : %1</translation>
        </message>
        <message>
            <source>The machine's position is not known yet (no status report with its work position): wait a moment, or set the reference pose.</source>
            <translation>La position de la machine n'est pas encore connue (aucun rapport d'état avec sa position de travail) : patientez un instant ou définissez la pose de référence.</translation>
        </message>
        <message>
            <source>The machine is still moving or busy: send a move when it stands still (Idle), so it can be checked from where the machine really is.</source>
            <translation>La machine bouge encore ou est occupée : envoyez un déplacement quand elle est à l'arrêt (Idle), pour qu'il soit vérifié depuis sa position réelle.</translation>
        </message>
        <message>
            <source>Console lines are sent UNCHECKED from now on.</source>
            <translation>Les lignes de la console sont désormais envoyées SANS VÉRIFICATION.</translation>
        </message>
        <message>
            <source>Console lines are checked again.</source>
            <translation>Les lignes de la console sont de nouveau vérifiées.</translation>
        </message>
        <message>
            <source>The machine must be connected, idle and its position known.</source>
            <translation>La machine doit être connectée, au repos et sa position connue.</translation>
        </message>
        <message>
            <source>The profile's home pose does not close the linkage.</source>
            <translation>La position d'origine du profil ne ferme pas la chaîne articulée.</translation>
        </message>
        <message>
            <source>No checked move to the home pose: %1</source>
            <translation>Pas de déplacement vérifié vers la position d'origine : %1</translation>
        </message>
        <message>
            <source>The move was not sent (see the console).</source>
            <translation>Le déplacement n'a pas été envoyé (voir la console).</translation>
        </message>
        <message>
            <source>choose a target inside the workspace</source>
            <translation>choisissez une cible dans l'espace de travail</translation>
        </message>
        <message>
            <source>Move not sent: %1</source>
            <translation>Mouvement non envoyé : %1</translation>
        </message>
        <message>
            <source>Home the machine (Home), or put the arms in the home pose and press Set reference pose.</source>
            <translation>Lancez la prise d'origine (Home), ou mettez les bras en pose d'origine et appuyez sur Définir la pose de référence.</translation>
        </message>
        <message>
            <source>Put the arms in the home pose by hand and press Set reference pose.</source>
            <translation>Mettez les bras à la main en pose d'origine et appuyez sur Définir la pose de référence.</translation>
        </message>
        <message>
            <source>Reading where the machine stands...</source>
            <translation>Lecture de la position de la machine…</translation>
        </message>
        <message>
            <source>The machine's position is not known: this board has not been referenced from this computer yet. %1</source>
            <translation>La position de la machine n'est pas connue : cette carte n'a pas encore été référencée depuis cet ordinateur. %1</translation>
        </message>
        <message>
            <source>The machine's position is not known: the board was powered up or reset since it was last seen, so the position it reports says nothing about where the arms stand. %1</source>
            <translation>La position de la machine n'est pas connue : la carte a été mise sous tension ou réinitialisée depuis la dernière fois, la position qu'elle indique ne dit donc rien de l'endroit où sont les bras. %1</translation>
        </message>
        <message>
            <source>The machine's position is not known: it was reset or stopped hard while moving, and the motors may have lost steps. %1</source>
            <translation>La position de la machine n'est pas connue : elle a été réinitialisée ou arrêtée brutalement en mouvement, les moteurs ont pu perdre des pas. %1</translation>
        </message>
        <message>
            <source>The machine's position is not known: the homing cycle moved the arms and did not finish. %1</source>
            <translation>La position de la machine n'est pas connue : la prise d'origine a déplacé les bras sans se terminer. %1</translation>
        </message>
        <message>
            <source>The machine's position is not known: it moved while no program watched it (a job cut off by a crash, a closed connection or another program). %1</source>
            <translation>La position de la machine n'est pas connue : elle a bougé sans qu'aucun programme ne la surveille (un travail interrompu par un plantage, une connexion fermée ou un autre programme). %1</translation>
        </message>
        <message>
            <source>Not connected.</source>
            <translation>Non connectée.</translation>
        </message>
        <message>
            <source>Moves are sent although the board's settings differ from the profile (expert override).</source>
            <translation>Les mouvements sont envoyés bien que les réglages de la carte diffèrent du profil (dérogation expert).</translation>
        </message>
        <message>
            <source>The machine is not connected.</source>
            <translation>La machine n'est pas connectée.</translation>
        </message>
        <message>
            <source>A job is running.</source>
            <translation>Un travail est en cours.</translation>
        </message>
        <message>
            <source>The board's settings %1 differ from the profile, so the machine would not move as planned: write the profile's settings (Machine settings...) first.</source>
            <translation>Les réglages %1 de la carte diffèrent du profil, la machine ne bougerait donc pas comme prévu : écrivez d'abord les réglages du profil (Réglages de la machine…).</translation>
        </message>
        <message>
            <source>The machine is not idle.</source>
            <translation>La machine n'est pas au repos.</translation>
        </message>
        <message>
            <source>Jog refused: %1</source>
            <translation>Déplacement refusé : %1</translation>
        </message>
        <message>
            <source>[feed override 100 %]</source>
            <translation>[correcteur d'avance 100 %]</translation>
        </message>
        <message>
            <source>[feed override +10 %]</source>
            <translation>[correcteur d'avance +10 %]</translation>
        </message>
        <message>
            <source>[feed override -10 %]</source>
            <translation>[correcteur d'avance -10 %]</translation>
        </message>
        <message>
            <source>[feed override +1 %]</source>
            <translation>[correcteur d'avance +1 %]</translation>
        </message>
        <message>
            <source>[feed override -1 %]</source>
            <translation>[correcteur d'avance -1 %]</translation>
        </message>
        <message>
            <source>[rapid override 100 %]</source>
            <translation>[correcteur de rapide 100 %]</translation>
        </message>
        <message>
            <source>[rapid override 50 %]</source>
            <translation>[correcteur de rapide 50 %]</translation>
        </message>
        <message>
            <source>[rapid override 25 %]</source>
            <translation>[correcteur de rapide 25 %]</translation>
        </message>
        <message numerus="yes">
            <source>%1 (jog in %n checked move(s))</source>
            <translation>
                <numerusform>%1 (déplacement en %n mouvement vérifié)</numerusform>
                <numerusform>%1 (déplacement en %n mouvements vérifiés)</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachineSettingsDialog</name>
        <message>
            <source>Machine settings</source>
            <translation>Réglages de la machine</translation>
        </message>
        <message>
            <source>The board's GRBL settings next to the values the machine profile needs. Writing saves a backup of the board's settings first.</source>
            <translation>Les réglages GRBL de la carte à côté des valeurs dont le profil de machine a besoin. L'écriture sauvegarde d'abord les réglages de la carte.</translation>
        </message>
        <message>
            <source>Setting</source>
            <translation>Réglage</translation>
        </message>
        <message>
            <source>Board</source>
            <translation>Carte</translation>
        </message>
        <message>
            <source>Profile</source>
            <translation>Profil</translation>
        </message>
        <message>
            <source>Differs</source>
            <translation>Diffère</translation>
        </message>
        <message>
            <source>Read from board</source>
            <translation>Lire depuis la carte</translation>
        </message>
        <message>
            <source>Write differences...</source>
            <translation>Écrire les différences…</translation>
        </message>
        <message>
            <source>Close</source>
            <translation>Fermer</translation>
        </message>
        <message>
            <source>The machine was disconnected.</source>
            <translation>La machine a été déconnectée.</translation>
        </message>
        <message>
            <source>Connect the machine first.</source>
            <translation>Connectez d'abord la machine.</translation>
        </message>
        <message>
            <source>A job is running.</source>
            <translation>Une tâche est en cours.</translation>
        </message>
        <message>
            <source>Still talking to the board.</source>
            <translation>Communication avec la carte en cours.</translation>
        </message>
        <message>
            <source>The machine must be idle (or in alarm) to change settings.</source>
            <translation>La machine doit être au repos (ou en alarme) pour changer les réglages.</translation>
        </message>
        <message>
            <source>Reading the board's settings...</source>
            <translation>Lecture des réglages de la carte…</translation>
        </message>
        <message>
            <source>Nothing to write: read the board's settings first.</source>
            <translation>Rien à écrire : lisez d'abord les réglages de la carte.</translation>
        </message>
        <message>
            <source>Write settings</source>
            <translation>Écrire les réglages</translation>
        </message>
        <message numerus="yes">
            <source>Write %n setting(s) to the board? Its current settings are saved to a backup file first.</source>
            <translation>
                <numerusform>Écrire %n réglage sur la carte ? Ses réglages actuels sont d'abord sauvegardés dans un fichier.</numerusform>
                <numerusform>Écrire %n réglages sur la carte ? Ses réglages actuels sont d'abord sauvegardés dans un fichier.</numerusform>
            </translation>
        </message>
        <message>
            <source>The board's settings match the profile.</source>
            <translation>Les réglages de la carte correspondent au profil.</translation>
        </message>
        <message numerus="yes">
            <source>%n setting(s) differ from the profile.</source>
            <translation>
                <numerusform>%n réglage diffère du profil.</numerusform>
                <numerusform>%n réglages diffèrent du profil.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n setting(s) written. Backup of the previous settings: %1</source>
            <translation>
                <numerusform>%n réglage écrit. Sauvegarde des réglages précédents : %1</numerusform>
                <numerusform>%n réglages écrits. Sauvegarde des réglages précédents : %1</numerusform>
            </translation>
        </message>
        <message>
            <source>Writing settings one at a time... Backup: %1</source>
            <translation>Écriture des réglages un par un… Sauvegarde : %1</translation>
        </message>
        <message>
            <source>Failed: %1</source>
            <translation>Échec : %1</translation>
        </message>
        <message>
            <source>yes</source>
            <translation>oui</translation>
        </message>
        <message>
            <source>Meaning</source>
            <translation>Signification</translation>
        </message>
        <message>
            <source>Unit</source>
            <translation>Unité</translation>
        </message>
        <message>
            <source>(not a GRBL 1.1h setting)</source>
            <translation>(pas un réglage de GRBL 1.1h)</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachinePanels</name>
        <message>
            <source>Machine</source>
            <translation>Machine</translation>
        </message>
        <message>
            <source>Run</source>
            <translation>Exécution</translation>
        </message>
        <message>
            <source>Jog</source>
            <translation>Déplacement</translation>
        </message>
        <message>
            <source>Console</source>
            <translation>Console</translation>
        </message>
        <message>
            <source>Machine profile</source>
            <translation>Profil</translation>
        </message>
        <message>
            <source>Machine &amp;settings...</source>
            <translation>&amp;Réglages de la machine…</translation>
        </message>
        <message>
            <source>A job is running</source>
            <translation>Une tâche est en cours</translation>
        </message>
        <message>
            <source>The machine is drawing "%1". Quitting the studio would leave it without its stream of lines.

Hold, stop and quit: the machine stops cleanly and the progress is saved, so you can resume later.</source>
            <translation>La machine trace « %1 ». Quitter le studio la priverait de son flux de lignes.

Pause, arrêter et quitter : la machine s'arrête proprement et la progression est enregistrée, vous pourrez reprendre plus tard.</translation>
        </message>
        <message>
            <source>Hold, stop and quit</source>
            <translation>Pause, arrêter et quitter</translation>
        </message>
        <message>
            <source>Keep running</source>
            <translation>Continuer</translation>
        </message>
        <message>
            <source>The job has ended</source>
            <translation>La tâche est terminée</translation>
        </message>
        <message>
            <source>The job "%1" has ended. Quit FiveBar Studio?</source>
            <translation>La tâche « %1 » est terminée. Quitter FiveBar Studio ?</translation>
        </message>
        <message>
            <source>Quit</source>
            <translation>Quitter</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Annuler</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ModePanel</name>
        <message>
            <source>Working mode</source>
            <translation>Mode de travail</translation>
        </message>
        <message>
            <source>Auto</source>
            <translation>Auto</translation>
        </message>
        <message>
            <source>Let the planner pick the feasible mode with the largest margin</source>
            <translation>Laisser le planificateur choisir le mode réalisable avec la plus grande marge</translation>
        </message>
        <message>
            <source>Elbows %1 (arm 1 %2, arm 2 %3)</source>
            <translation>Coudes %1 (bras 1 %2, bras 2 %3)</translation>
        </message>
        <message>
            <source>out</source>
            <translation>dehors</translation>
        </message>
        <message>
            <source>in</source>
            <translation>dedans</translation>
        </message>
        <message>
            <source>Overlays</source>
            <translation>Superpositions</translation>
        </message>
        <message>
            <source>Reachable and singularity-free regions</source>
            <translation>Zones atteignables et sans singularité</translation>
        </message>
        <message>
            <source>Type II singularity curves</source>
            <translation>Courbes de singularité de type II</translation>
        </message>
        <message>
            <source>Largest singularity-free rectangle</source>
            <translation>Plus grand rectangle sans singularité</translation>
        </message>
        <message>
            <source>Workspace legend</source>
            <translation>Légende de l'espace de travail</translation>
        </message>
        <message>
            <source>None</source>
            <translation>Aucune</translation>
        </message>
        <message>
            <source>Transmission angle</source>
            <translation>Angle de transmission</translation>
        </message>
        <message>
            <source>Conditioning</source>
            <translation>Conditionnement</translation>
        </message>
        <message>
            <source>Resolution (mm per step)</source>
            <translation>Résolution (mm par pas)</translation>
        </message>
        <message>
            <source>Map:</source>
            <translation>Carte :</translation>
        </message>
        <message>
            <source>Auto picked %1.</source>
            <translation>Auto a choisi %1.</translation>
        </message>
        <message>
            <source>Auto: no mode draws the whole job; showing %1.</source>
            <translation>Auto : aucun mode ne trace toute la tâche ; affichage de %1.</translation>
        </message>
        <message>
            <source>Showing the workspace of %1.</source>
            <translation>Espace de travail de %1 affiché.</translation>
        </message>
        <message>
            <source>Smallest singularity margin: %1 deg.</source>
            <translation>Plus petite marge de singularité : %1°.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ParetoPlot</name>
        <message>
            <source>Footprint (cm²)</source>
            <translation>Encombrement (cm²)</translation>
        </message>
        <message>
            <source>Worst condition number</source>
            <translation>Pire conditionnement</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::PlacementPanel</name>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> deg</source>
            <translation> °</translation>
        </message>
        <message>
            <source> %</source>
            <translation> %</translation>
        </message>
        <message>
            <source>Centre X:</source>
            <translation>Centre X :</translation>
        </message>
        <message>
            <source>Centre Y:</source>
            <translation>Centre Y :</translation>
        </message>
        <message>
            <source>Rotation:</source>
            <translation>Rotation :</translation>
        </message>
        <message>
            <source>Scale:</source>
            <translation>Échelle :</translation>
        </message>
        <message>
            <source>Fit to workspace</source>
            <translation>Ajuster à l'espace</translation>
        </message>
        <message>
            <source>Keep aspect ratio</source>
            <translation>Garder les proportions</translation>
        </message>
        <message>
            <source>Width:</source>
            <translation>Largeur :</translation>
        </message>
        <message>
            <source>Height:</source>
            <translation>Hauteur :</translation>
        </message>
        <message>
            <source>Actual size</source>
            <translation>Taille réelle</translation>
        </message>
        <message>
            <source>Draw the drawing at its true size (100 %)</source>
            <translation>Tracer le dessin à sa taille réelle (100 %)</translation>
        </message>
        <message>
            <source>Scale the drawing to fill the largest singularity-free rectangle</source>
            <translation>Mettre le dessin à l'échelle du plus grand rectangle sans singularité</translation>
        </message>
        <message>
            <source>No singularity-free area to fit the drawing into.</source>
            <translation>Aucune zone sans singularité où ajuster le dessin.</translation>
        </message>
        <message>
            <source>Fitted: %1 %</source>
            <translation>Ajusté : %1 %</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::PreviewPanel</name>
        <message>
            <source>%1 % of what this machine can do</source>
            <translation>%1 % du maximum possible</translation>
        </message>
        <message>
            <source>%1 s</source>
            <translation>%1 s</translation>
        </message>
        <message>
            <source>%1 h %2 min</source>
            <translation>%1 h %2 min</translation>
        </message>
        <message>
            <source>%1 min %2 s</source>
            <translation>%1 min %2 s</translation>
        </message>
        <message>
            <source>Show</source>
            <translation>Afficher</translation>
        </message>
        <message>
            <source>Colour pen-down moves by speed</source>
            <translation>Colorer les tracés selon la vitesse</translation>
        </message>
        <message>
            <source>Pen-up moves (grey)</source>
            <translation>Déplacements stylo levé (gris)</translation>
        </message>
        <message>
            <source>Drawing order</source>
            <translation>Ordre de tracé</translation>
        </message>
        <message>
            <source>Pre-flight problems (click to show):</source>
            <translation>Problèmes avant tracé (cliquer pour voir) :</translation>
        </message>
        <message>
            <source>Moves shown: %1 of %2</source>
            <translation>Mouvements affichés : %1 sur %2</translation>
        </message>
        <message>
            <source>Planning...</source>
            <translation>Planification…</translation>
        </message>
        <message>
            <source>Planned.</source>
            <translation>Planifié.</translation>
        </message>
        <message>
            <source>Open a drawing to plan a job.</source>
            <translation>Ouvrez un dessin pour planifier une tâche.</translation>
        </message>
        <message>
            <source>Working mode: &lt;b&gt;%1&lt;/b&gt;</source>
            <translation>Mode de travail : &lt;b&gt;%1&lt;/b&gt;</translation>
        </message>
        <message>
            <source>No problems: every move is reachable and safe.</source>
            <translation>Aucun problème : chaque mouvement est atteignable et sûr.</translation>
        </message>
        <message>
            <source>What to do: %1</source>
            <translation>Que faire : %1</translation>
        </message>
        <message>
            <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Working mode:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Estimated time:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;%8&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pen down:&lt;/td&gt;&lt;td&gt;%3 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pen up:&lt;/td&gt;&lt;td&gt;%4 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Segments:&lt;/td&gt;&lt;td&gt;%5&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Max deviation:&lt;/td&gt;&lt;td&gt;%6 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Singularity margin:&lt;/td&gt;&lt;td&gt;%7 deg&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
            <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Mode de travail :&lt;/td&gt;&lt;td&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Durée estimée :&lt;/td&gt;&lt;td&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;%8&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Stylo baissé :&lt;/td&gt;&lt;td&gt;%3 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Stylo levé :&lt;/td&gt;&lt;td&gt;%4 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Segments :&lt;/td&gt;&lt;td&gt;%5&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Écart max. :&lt;/td&gt;&lt;td&gt;%6 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Marge de singularité :&lt;/td&gt;&lt;td&gt;%7°&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
        </message>
        <message>
            <source>; </source>
            <translation> ; </translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ProfileEditor</name>
        <message>
            <source>Load preset</source>
            <translation>Charger un préréglage</translation>
        </message>
        <message>
            <source>Import…</source>
            <translation>Importer…</translation>
        </message>
        <message>
            <source>Load a machine profile from a JSON file</source>
            <translation>Charger un profil de machine depuis un fichier JSON</translation>
        </message>
        <message>
            <source>Export…</source>
            <translation>Exporter…</translation>
        </message>
        <message>
            <source>Save this machine profile as a JSON file</source>
            <translation>Enregistrer ce profil de machine en fichier JSON</translation>
        </message>
        <message>
            <source>Machine</source>
            <translation>Machine</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>Nom</translation>
        </message>
        <message>
            <source>Geometry</source>
            <translation>Géométrie</translation>
        </message>
        <message>
            <source>Joint limits</source>
            <translation>Limites articulaires</translation>
        </message>
        <message>
            <source>Motors</source>
            <translation>Moteurs</translation>
        </message>
        <message>
            <source>Tool</source>
            <translation>Outil</translation>
        </message>
        <message>
            <source>Motion and safety</source>
            <translation>Mouvement et sécurité</translation>
        </message>
        <message>
            <source>Connection and home pose</source>
            <translation>Connexion et pose d'origine</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> °</source>
            <translation> °</translation>
        </message>
        <message>
            <source> s</source>
            <translation> s</translation>
        </message>
        <message>
            <source>Limit the motor angles</source>
            <translation>Limiter les angles des moteurs</translation>
        </message>
        <message>
            <source> °/min</source>
            <translation> °/min</translation>
        </message>
        <message>
            <source> °/s²</source>
            <translation> °/s²</translation>
        </message>
        <message>
            <source>Pen servo (M3 S / M5)</source>
            <translation>Servo de stylo (M3 S / M5)</translation>
        </message>
        <message>
            <source>Z axis</source>
            <translation>Axe Z</translation>
        </message>
        <message>
            <source>Laser (M4 S / M5)</source>
            <translation>Laser (M4 S / M5)</translation>
        </message>
        <message>
            <source> mm/min</source>
            <translation> mm/min</translation>
        </message>
        <message>
            <source>Working mode (built)</source>
            <translation>Mode de travail (montage)</translation>
        </message>
        <message>
            <source>Assembly mode</source>
            <translation>Mode d'assemblage</translation>
        </message>
        <message>
            <source> mm/s</source>
            <translation> mm/s</translation>
        </message>
        <message>
            <source>The machine has homing switches ($H)</source>
            <translation>La machine a des capteurs d'origine ($H)</translation>
        </message>
        <message>
            <source>The profile is not applied until these problems are fixed.</source>
            <translation>Le profil n'est pas appliqué tant que ces problèmes ne sont pas corrigés.</translation>
        </message>
        <message>
            <source>%1 cannot be used:
%2</source>
            <translation>%1 ne peut pas être utilisé :
%2</translation>
        </message>
        <message>
            <source>Fix the profile's problems before exporting it.</source>
            <translation>Corrigez les problèmes du profil avant de l'exporter.</translation>
        </message>
        <message>
            <source>Import machine profile</source>
            <translation>Importer un profil de machine</translation>
        </message>
        <message>
            <source>Machine profiles (*.json)</source>
            <translation>Profils de machine (*.json)</translation>
        </message>
        <message>
            <source>Import failed</source>
            <translation>Échec de l'import</translation>
        </message>
        <message>
            <source>Export machine profile</source>
            <translation>Exporter le profil de machine</translation>
        </message>
        <message>
            <source>Export failed</source>
            <translation>Échec de l'export</translation>
        </message>
        <message>
            <source> steps/°</source>
            <translation> pas/°</translation>
        </message>
        <message>
            <source> baud</source>
            <translation> bauds</translation>
        </message>
    </context>
    <context>
        <name>ProfileField</name>
        <message>
            <source>Driving link a1</source>
            <translation>Bras moteur a1</translation>
        </message>
        <message>
            <source>Floating link b1</source>
            <translation>Bras libre b1</translation>
        </message>
        <message>
            <source>Driving link a2</source>
            <translation>Bras moteur a2</translation>
        </message>
        <message>
            <source>Floating link b2</source>
            <translation>Bras libre b2</translation>
        </message>
        <message>
            <source>Motor distance w</source>
            <translation>Entraxe des moteurs w</translation>
        </message>
        <message>
            <source>θ1 minimum</source>
            <translation>θ1 minimum</translation>
        </message>
        <message>
            <source>θ1 maximum</source>
            <translation>θ1 maximum</translation>
        </message>
        <message>
            <source>θ2 minimum</source>
            <translation>θ2 minimum</translation>
        </message>
        <message>
            <source>θ2 maximum</source>
            <translation>θ2 maximum</translation>
        </message>
        <message>
            <source>Motor 1 steps per degree</source>
            <translation>Moteur 1 : pas par degré</translation>
        </message>
        <message>
            <source>Motor 2 steps per degree</source>
            <translation>Moteur 2 : pas par degré</translation>
        </message>
        <message>
            <source>Motor 1 maximum speed</source>
            <translation>Moteur 1 : vitesse maximale</translation>
        </message>
        <message>
            <source>Motor 2 maximum speed</source>
            <translation>Moteur 2 : vitesse maximale</translation>
        </message>
        <message>
            <source>Motor 1 acceleration</source>
            <translation>Moteur 1 : accélération</translation>
        </message>
        <message>
            <source>Motor 2 acceleration</source>
            <translation>Moteur 2 : accélération</translation>
        </message>
        <message>
            <source>Junction deviation</source>
            <translation>Déviation de jonction</translation>
        </message>
        <message>
            <source>Pen up S value</source>
            <translation>Valeur S stylo levé</translation>
        </message>
        <message>
            <source>Pen down S value</source>
            <translation>Valeur S stylo baissé</translation>
        </message>
        <message>
            <source>Pen up delay</source>
            <translation>Délai stylo levé</translation>
        </message>
        <message>
            <source>Pen down delay</source>
            <translation>Délai stylo baissé</translation>
        </message>
        <message>
            <source>Z up</source>
            <translation>Z haut</translation>
        </message>
        <message>
            <source>Z down</source>
            <translation>Z bas</translation>
        </message>
        <message>
            <source>Z feed</source>
            <translation>Avance Z</translation>
        </message>
        <message>
            <source>Laser power S value</source>
            <translation>Valeur S de puissance laser</translation>
        </message>
        <message>
            <source>Drawing speed</source>
            <translation>Vitesse de tracé</translation>
        </message>
        <message>
            <source>Travel speed</source>
            <translation>Vitesse de déplacement</translation>
        </message>
        <message>
            <source>Type II singularity margin</source>
            <translation>Marge de singularité de type II</translation>
        </message>
        <message>
            <source>Type I singularity margin</source>
            <translation>Marge de singularité de type I</translation>
        </message>
        <message>
            <source>Baud rate</source>
            <translation>Débit en bauds</translation>
        </message>
        <message>
            <source>Home θ1</source>
            <translation>Origine θ1</translation>
        </message>
        <message>
            <source>Home θ2</source>
            <translation>Origine θ2</translation>
        </message>
        <message>
            <source>Calibration format version</source>
            <translation>Version du format d'étalonnage</translation>
        </message>
        <message>
            <source>Held-out marks</source>
            <translation>Marques mises de côté</translation>
        </message>
        <message>
            <source>Largest residual of the fit</source>
            <translation>Plus grand résidu de l'ajustement</translation>
        </message>
        <message>
            <source>Marks used by the fit</source>
            <translation>Marques utilisées par l'ajustement</translation>
        </message>
        <message>
            <source>Motor 1 backlash</source>
            <translation>Jeu du moteur 1</translation>
        </message>
        <message>
            <source>Motor 1 zero offset</source>
            <translation>Décalage du zéro du moteur 1</translation>
        </message>
        <message>
            <source>Motor 2 backlash</source>
            <translation>Jeu du moteur 2</translation>
        </message>
        <message>
            <source>Motor 2 zero offset</source>
            <translation>Décalage du zéro du moteur 2</translation>
        </message>
        <message>
            <source>Pen offset across b1</source>
            <translation>Décalage du stylo en travers de b1</translation>
        </message>
        <message>
            <source>Pen offset along b1</source>
            <translation>Décalage du stylo le long de b1</translation>
        </message>
        <message>
            <source>RMS error on held-out marks</source>
            <translation>Erreur RMS sur les marques mises de côté</translation>
        </message>
        <message>
            <source>RMS residual of the fit</source>
            <translation>Résidu RMS de l'ajustement</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::RunController</name>
        <message>
            <source>Not started: the board's soft limits would stop this job with an alarm (ALARM:2): %1. The board checks its travel ($130, $131) in machine coordinates, which the reference pose shifted against the drawing's. Home the machine, or make the board's settings match the profile (Machine settings...), then start again.</source>
            <translation>Non démarré : les limites logicielles de la carte arrêteraient ce travail par une alarme (ALARM:2) : %1. La carte vérifie sa course ($130, $131) en coordonnées machine, que la pose de référence a décalées par rapport à celles du dessin. Faites la prise d'origine de la machine, ou alignez les réglages de la carte sur le profil (Réglages de la machine…), puis relancez.</translation>
        </message>
        <message>
            <source>The connection was closed during the run. The progress is saved beside the job: reconnect and resume.</source>
            <translation>La connexion a été fermée pendant l'exécution. La progression est enregistrée à côté de la tâche : reconnectez et reprenez.</translation>
        </message>
        <message>
            <source>Cannot start: connect the machine, wait until it is idle, and let the job plan first.</source>
            <translation>Impossible de démarrer : connectez la machine, attendez qu'elle soit au repos et laissez d'abord la tâche se planifier.</translation>
        </message>
        <message>
            <source>Cannot create the job folder %1.</source>
            <translation>Impossible de créer le dossier de tâche %1.</translation>
        </message>
        <message>
            <source>Nothing to resume: there is no saved progress beside %1.</source>
            <translation>Rien à reprendre : aucune progression enregistrée à côté de %1.</translation>
        </message>
        <message>
            <source>line %1 of %2</source>
            <translation>ligne %1 sur %2</translation>
        </message>
        <message>
            <source>The run of "%1" was interrupted at %2: %3</source>
            <translation>L'exécution de « %1 » a été interrompue à %2 : %3</translation>
        </message>
        <message>
            <source>press Resume</source>
            <translation>appuyez sur Reprendre</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>Reprendre</translation>
        </message>
        <message>
            <source>The machine raised an alarm and the job stopped (the banner in the Machine panel says why). The progress is saved: clear the alarm (Reset, Unlock), check the pen stands where the studio shows it, then press Resume.</source>
            <translation>La machine a déclenché une alarme et la tâche s'est arrêtée (le bandeau du panneau Machine indique pourquoi). La progression est enregistrée : acquittez l'alarme (Reset, Unlock), vérifiez que le stylo est bien là où le studio l'affiche, puis appuyez sur Reprendre.</translation>
        </message>
        <message>
            <source>Resuming "%1"…</source>
            <translation>Reprise de « %1 »…</translation>
        </message>
        <message>
            <source>Running "%1"…</source>
            <translation>Exécution de « %1 »…</translation>
        </message>
        <message>
            <source>"%1" is drawn.</source>
            <translation>« %1 » est tracé.</translation>
        </message>
        <message>
            <source>Not started: %1</source>
            <translation>Non démarré : %1</translation>
        </message>
        <message>
            <source>The run of "%1" was interrupted after %2: %3</source>
            <translation>L'exécution de « %1 » a été interrompue après %2 : %3</translation>
        </message>
        <message>
            <source>The drawing, its placement, the machine profile or the tolerance changed since, so Resume would draw the old job where the canvas no longer shows it: undo the change to resume, or press Start to draw the new one from the beginning.</source>
            <translation>Le dessin, son placement, le profil de la machine ou la tolérance ont changé depuis, Reprendre dessinerait donc l'ancien travail là où le canevas ne le montre plus : annulez la modification pour reprendre, ou appuyez sur Démarrer pour dessiner le nouveau depuis le début.</translation>
        </message>
        <message>
            <source>Not started: the board's settings differ from the profile. %1 Write the profile's settings (Machine settings...), or choose Start anyway when Start asks.</source>
            <translation>Non démarré : les réglages de la carte diffèrent du profil. %1 Écrivez les réglages du profil (Réglages de la machine…), ou choisissez Démarrer quand même lorsque Démarrer le demande.</translation>
        </message>
        <message>
            <source>Stopped before the first move: nothing was sent.</source>
            <translation>Arrêté avant le premier mouvement : rien n'a été envoyé.</translation>
        </message>
        <message>
            <source>Stopped after line %1 of %2; the pen is up and the machine at rest.</source>
            <translation>Arrêté après la ligne %1 sur %2 ; le stylo est levé et la machine à l'arrêt.</translation>
        </message>
        <message>
            <source>Stopped after line %1 of %2; the pen could not be lifted.</source>
            <translation>Arrêté après la ligne %1 sur %2 ; le stylo n'a pas pu être levé.</translation>
        </message>
        <message>
            <source>The progress is saved: press Resume to continue.</source>
            <translation>La progression est enregistrée : appuyez sur Reprendre pour continuer.</translation>
        </message>
        <message>
            <source>Stopped after line %1 of %2: %3 The progress is saved: press Resume to continue.</source>
            <translation>Arrêté après la ligne %1 sur %2 : %3 La progression est enregistrée : appuyez sur Reprendre pour continuer.</translation>
        </message>
        <message>
            <source>Not resumed: the job is not planned yet; wait for the preview.</source>
            <translation>Non repris : le travail n'est pas encore planifié ; attendez l'aperçu.</translation>
        </message>
        <message>
            <source>Not resumed: the drawing, its placement, the machine profile or the tolerance changed since the run was interrupted, so Resume would draw the old job where the canvas no longer shows it. Undo the change to resume, or press Start to draw the new one from the beginning.</source>
            <translation>Non repris : le dessin, son placement, le profil de la machine ou la tolérance ont changé depuis l'interruption, Reprendre dessinerait donc l'ancien travail là où le canevas ne le montre plus. Annulez la modification pour reprendre, ou appuyez sur Démarrer pour dessiner le nouveau depuis le début.</translation>
        </message>
        <message>
            <source>Cannot resume: connect the machine and wait until it is idle.</source>
            <translation>Impossible de reprendre : connectez la machine et attendez qu'elle soit au repos.</translation>
        </message>
        <message>
            <source>Not resumed: %1</source>
            <translation>Non repris : %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::OverrideControls</name>
        <message>
            <source>Overrides</source>
            <translation>Correcteurs</translation>
        </message>
        <message>
            <source>The machine scales the job's feed (10 to 200 %) and its rapid moves (25, 50 or 100 %) at once. It never exceeds its maximum rates ($110, $111): a higher feed override stops speeding up where the motors' limit is.</source>
            <translation>La machine ajuste aussitôt l'avance du travail (10 à 200 %) et ses déplacements rapides (25, 50 ou 100 %). Elle ne dépasse jamais ses vitesses maximales ($110, $111) : au-delà de la limite des moteurs, un correcteur d'avance plus élevé n'accélère plus.</translation>
        </message>
        <message>
            <source>Feed override: pen-down and other G1 moves</source>
            <translation>Correcteur d'avance : déplacements stylo baissé et autres mouvements G1</translation>
        </message>
        <message>
            <source>Rapid override: G0 travel moves</source>
            <translation>Correcteur de rapide : déplacements G0</translation>
        </message>
        <message>
            <source>Feed</source>
            <translation>Avance</translation>
        </message>
        <message>
            <source>−10 %</source>
            <translation>−10 %</translation>
        </message>
        <message>
            <source>Alt+Down</source>
            <translation>Alt+Down</translation>
        </message>
        <message>
            <source>−1 %</source>
            <translation>−1 %</translation>
        </message>
        <message>
            <source>Alt+Left</source>
            <translation>Alt+Left</translation>
        </message>
        <message>
            <source>100 %</source>
            <translation>100 %</translation>
        </message>
        <message>
            <source>Alt+0</source>
            <translation>Alt+0</translation>
        </message>
        <message>
            <source>+1 %</source>
            <translation>+1 %</translation>
        </message>
        <message>
            <source>Alt+Right</source>
            <translation>Alt+Right</translation>
        </message>
        <message>
            <source>+10 %</source>
            <translation>+10 %</translation>
        </message>
        <message>
            <source>Alt+Up</source>
            <translation>Alt+Up</translation>
        </message>
        <message>
            <source>Rapid</source>
            <translation>Rapide</translation>
        </message>
        <message>
            <source>25 %</source>
            <translation>25 %</translation>
        </message>
        <message>
            <source>Alt+4</source>
            <translation>Alt+4</translation>
        </message>
        <message>
            <source>50 %</source>
            <translation>50 %</translation>
        </message>
        <message>
            <source>Alt+2</source>
            <translation>Alt+2</translation>
        </message>
        <message>
            <source>Alt+1</source>
            <translation>Alt+1</translation>
        </message>
        <message>
            <source>%1 %</source>
            <translation>%1 %</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::RunPanel</name>
        <message>
            <source>Ready</source>
            <translation>Prêt</translation>
        </message>
        <message>
            <source>Running</source>
            <translation>En marche</translation>
        </message>
        <message>
            <source>Holding…</source>
            <translation>Mise en pause…</translation>
        </message>
        <message>
            <source>On hold</source>
            <translation>En pause</translation>
        </message>
        <message>
            <source>Paused by a problem</source>
            <translation>En pause à cause d'un problème</translation>
        </message>
        <message>
            <source>Stopping…</source>
            <translation>Arrêt…</translation>
        </message>
        <message>
            <source>Stopped</source>
            <translation>Arrêté</translation>
        </message>
        <message>
            <source>Finished</source>
            <translation>Terminé</translation>
        </message>
        <message>
            <source>%1 h %2 min</source>
            <translation>%1 h %2 min</translation>
        </message>
        <message>
            <source>%1 min %2 s</source>
            <translation>%1 min %2 s</translation>
        </message>
        <message>
            <source>%1 s</source>
            <translation>%1 s</translation>
        </message>
        <message>
            <source>Start</source>
            <translation>Démarrer</translation>
        </message>
        <message>
            <source>Write the planned job as G-code and stream it to the machine</source>
            <translation>Écrire la tâche planifiée en G-code et l'envoyer à la machine</translation>
        </message>
        <message>
            <source>Hold</source>
            <translation>Pause</translation>
        </message>
        <message>
            <source>Feed hold: the machine decelerates and waits</source>
            <translation>Pause d'avance : la machine ralentit et attend</translation>
        </message>
        <message>
            <source>Continue</source>
            <translation>Continuer</translation>
        </message>
        <message>
            <source>Continue after a hold</source>
            <translation>Continuer après une pause</translation>
        </message>
        <message>
            <source>Stop</source>
            <translation>Arrêter</translation>
        </message>
        <message>
            <source>Stop the job: hold, reset and unlock; the progress is kept for a resume</source>
            <translation>Arrêter la tâche : pause, réinitialisation et déverrouillage ; la progression est gardée pour une reprise</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>Reprendre</translation>
        </message>
        <message>
            <source>Continue the interrupted job from its last completed pen-down point, with a safe pen-up approach</source>
            <translation>Reprendre la tâche interrompue à partir de son dernier point tracé, avec une approche sûre stylo levé</translation>
        </message>
        <message>
            <source>No job sent yet</source>
            <translation>Aucune tâche envoyée</translation>
        </message>
        <message>
            <source>%1 left</source>
            <translation>reste %1</translation>
        </message>
        <message>
            <source>Long job</source>
            <translation>Tâche longue</translation>
        </message>
        <message>
            <source>Start from the beginning?</source>
            <translation>Recommencer depuis le début ?</translation>
        </message>
        <message>
            <source>%1

Start draws "%2" from the beginning and discards this saved progress. Resume continues the interrupted run instead.</source>
            <translation>%1

Démarrer trace « %2 » depuis le début et abandonne cette progression enregistrée. Reprendre poursuit plutôt l'exécution interrompue.</translation>
        </message>
        <message>
            <source>Discard and start over</source>
            <translation>Abandonner et recommencer</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Annuler</translation>
        </message>
        <message>
            <source>Reading the board's settings to compare them with the profile: press Start again in a moment.</source>
            <translation>Lecture des réglages de la carte pour les comparer au profil : appuyez de nouveau sur Démarrer dans un instant.</translation>
        </message>
        <message>
            <source>The board's settings differ</source>
            <translation>Les réglages de la carte diffèrent</translation>
        </message>
        <message>
            <source>Write the profile's settings...</source>
            <translation>Écrire les réglages du profil...</translation>
        </message>
        <message>
            <source>Start anyway</source>
            <translation>Démarrer quand même</translation>
        </message>
        <message>
            <source>%1 % (%2)</source>
            <translation>%1 % (%2)</translation>
        </message>
        <message>
            <source>%1 left (on hold)</source>
            <translation>%1 restant (en pause)</translation>
        </message>
        <message>
            <source>Machine time left by the plan, planned again at the feed and rapid override the machine reports</source>
            <translation>Temps machine restant selon le plan, replanifié avec les correcteurs d'avance et de rapide que la machine signale</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::SettingsAdvice</name>
        <message>
            <source>soft limits are on, but this machine has no homing switches: the board measures its travel from where it was switched on, not from the reference pose, and stops the job with ALARM:2 when a move leaves that range.</source>
            <translation>les limites logicielles sont actives, mais cette machine n'a pas de fins de course de homing : la carte mesure sa course depuis sa position à la mise sous tension, pas depuis la pose de référence, et arrête la tâche avec ALARM:2 quand un déplacement sort de cette plage.</translation>
        </message>
        <message>
            <source>soft limits are off although the profile expects them.</source>
            <translation>les limites logicielles sont désactivées alors que le profil les attend.</translation>
        </message>
        <message>
            <source>hard limits are on: without limit switches wired, noise on the pins stops the machine with ALARM:1.</source>
            <translation>les limites matérielles sont actives : sans fins de course câblés, du bruit sur les broches arrête la machine avec ALARM:1.</translation>
        </message>
        <message>
            <source>hard limits are off although the profile expects them.</source>
            <translation>les limites matérielles sont désactivées alors que le profil les attend.</translation>
        </message>
        <message>
            <source>the homing cycle is on: the board starts locked and wants $H, which needs homing switches.</source>
            <translation>le cycle de homing est actif : la carte démarre verrouillée et attend $H, qui nécessite des fins de course.</translation>
        </message>
        <message>
            <source>the homing cycle is off although the profile has switches.</source>
            <translation>le cycle de homing est désactivé alors que le profil a des fins de course.</translation>
        </message>
        <message>
            <source>steps per degree differ: every motor angle would be wrong by the ratio, so the arms would leave the checked, safe poses.</source>
            <translation>les pas par degré diffèrent : chaque angle moteur serait faux dans ce rapport, et les bras quitteraient les poses vérifiées et sûres.</translation>
        </message>
        <message>
            <source>the board's maximum rate is lower: the job runs slower than planned and the time estimate is off.</source>
            <translation>la vitesse maximale de la carte est plus basse : la tâche est plus lente que prévu et l'estimation du temps est fausse.</translation>
        </message>
        <message>
            <source>the board's maximum rate is higher than the profile allows: the motors may lose steps.</source>
            <translation>la vitesse maximale de la carte dépasse ce que le profil permet : les moteurs peuvent perdre des pas.</translation>
        </message>
        <message>
            <source>the board accelerates more gently: the job takes longer than planned.</source>
            <translation>la carte accélère plus doucement : la tâche dure plus longtemps que prévu.</translation>
        </message>
        <message>
            <source>the board accelerates harder than the profile allows: the motors may lose steps.</source>
            <translation>la carte accélère plus fort que ce que le profil permet : les moteurs peuvent perdre des pas.</translation>
        </message>
        <message>
            <source>the motor's travel for soft limits differs: with soft limits on, a move beyond it stops the job with ALARM:2.</source>
            <translation>la course du moteur pour les limites logicielles diffère : avec les limites logicielles actives, un déplacement au-delà arrête la tâche avec ALARM:2.</translation>
        </message>
        <message>
            <source>the spindle (pen servo / laser) range differs: the pen may not lift or lower as planned.</source>
            <translation>la plage de la broche (servo de stylo / laser) diffère : le stylo risque de ne pas se lever ou s'abaisser comme prévu.</translation>
        </message>
        <message>
            <source>the junction deviation differs: corners run at other speeds than planned.</source>
            <translation>la déviation de jonction diffère : les angles sont parcourus à d'autres vitesses que prévu.</translation>
        </message>
        <message>
            <source>differs from what the profile expects.</source>
            <translation>diffère de ce qu'attend le profil.</translation>
        </message>
        <message>
            <source>not reported</source>
            <translation>non signalé</translation>
        </message>
        <message>
            <source>$%1 is %2 on the board, the profile wants %3: %4</source>
            <translation>$%1 vaut %2 sur la carte, le profil attend %3 : %4</translation>
        </message>
        <message numerus="yes">
            <source>The board's settings differ from the profile in %n place(s): %1.</source>
            <translation>
                <numerusform>Les réglages de la carte diffèrent du profil en %n endroit : %1.</numerusform>
                <numerusform>Les réglages de la carte diffèrent du profil en %n endroits : %1.</numerusform>
            </translation>
        </message>
        <message>
            <source>A job would stop or move wrongly with them.</source>
            <translation>Une tâche s'arrêterait ou se déplacerait mal avec eux.</translation>
        </message>
        <message>
            <source>The board's GRBL settings differ from the machine profile, and the job would not run as planned:</source>
            <translation>Les réglages GRBL de la carte diffèrent du profil machine, et la tâche ne se déroulerait pas comme prévu :</translation>
        </message>
        <message>
            <source>The board's GRBL settings differ from the machine profile:</source>
            <translation>Les réglages GRBL de la carte diffèrent du profil machine :</translation>
        </message>
        <message>
            <source>Write the profile's settings to the board (its current ones are saved to a backup file first), or start anyway.</source>
            <translation>Écrivez les réglages du profil sur la carte (les actuels sont d'abord sauvegardés dans un fichier), ou démarrez quand même.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::SimulationPanel</name>
        <message>
            <source>Step back one move</source>
            <translation>Reculer d'un mouvement</translation>
        </message>
        <message>
            <source>Play / pause the simulation</source>
            <translation>Lire / mettre en pause la simulation</translation>
        </message>
        <message>
            <source>Step forward one move</source>
            <translation>Avancer d'un mouvement</translation>
        </message>
        <message>
            <source>Simulation speed</source>
            <translation>Vitesse de simulation</translation>
        </message>
        <message>
            <source>x%1</source>
            <translation>x%1</translation>
        </message>
        <message>
            <source>No planned job to simulate.</source>
            <translation>Aucune tâche planifiée à simuler.</translation>
        </message>
        <message>
            <source>%1 of %2</source>
            <translation>%1 sur %2</translation>
        </message>
        <message>
            <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Motor angles:&lt;/td&gt;&lt;td&gt;%1 deg, %2 deg&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pen:&lt;/td&gt;&lt;td&gt;x %3 mm, y %4 mm (%5)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Transmission angle:&lt;/td&gt;&lt;td&gt;%6 deg at the pen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;%7 / %8 deg at the elbows&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Type II margin:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%9 deg&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
            <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Angles moteurs :&lt;/td&gt;&lt;td&gt;%1°, %2°&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Stylo :&lt;/td&gt;&lt;td&gt;x %3 mm, y %4 mm (%5)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Angle de transmission :&lt;/td&gt;&lt;td&gt;%6° au stylo&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;%7° / %8° aux coudes&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Marge type II :&lt;/td&gt;&lt;td&gt;&lt;b&gt;%9°&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
        </message>
        <message>
            <source>down</source>
            <translation>baissé</translation>
        </message>
        <message>
            <source>up</source>
            <translation>levé</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::SpeedLegend</name>
        <message>
            <source>0 mm/s</source>
            <translation>0 mm/s</translation>
        </message>
        <message>
            <source>%1 mm/s</source>
            <translation>%1 mm/s</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::StudioDocument</name>
        <message>
            <source>Show layer</source>
            <translation>Afficher le calque</translation>
        </message>
        <message>
            <source>Hide layer</source>
            <translation>Masquer le calque</translation>
        </message>
        <message>
            <source>Reorder layers</source>
            <translation>Réordonner les calques</translation>
        </message>
        <message>
            <source>Change layer tool settings</source>
            <translation>Changer les réglages d'outil du calque</translation>
        </message>
        <message>
            <source>Change layer fill</source>
            <translation>Modifier le remplissage du calque</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::AccuracyPage</name>
        <message>
            <source>Measure the accuracy lines</source>
            <translation>Mesurer les lignes de précision</translation>
        </message>
        <message>
            <source>Hoang's accuracy pattern is ten lines, each meant to be 40 mm long and straight, 10 mm apart. Lay a steel ruler along each line. &lt;b&gt;Length&lt;/b&gt;: from end to end, in the middle of the pen's stroke. &lt;b&gt;Straightness&lt;/b&gt;: the widest gap between the line and the ruler's edge when the ruler touches both ends (0 for a straight line). Type the lines drawn &lt;b&gt;before&lt;/b&gt; calibration in the first two columns and those of the verification sheet (drawn &lt;b&gt;after&lt;/b&gt;) in the last two; the figures below compare them.</source>
            <translation>Le motif de précision de Hoang compte dix lignes, chacune censée être longue de 40 mm et droite, espacées de 10 mm. Posez une règle en acier le long de chaque ligne. &lt;b&gt;Longueur&lt;/b&gt; : d'un bout à l'autre, au milieu du trait du stylo. &lt;b&gt;Rectitude&lt;/b&gt; : le plus grand écart entre la ligne et le bord de la règle quand la règle touche les deux bouts (0 pour une ligne droite). Saisissez les lignes tracées &lt;b&gt;avant&lt;/b&gt; l'étalonnage dans les deux premières colonnes et celles de la feuille de vérification (tracées &lt;b&gt;après&lt;/b&gt;) dans les deux dernières ; les chiffres ci-dessous les comparent.</translation>
        </message>
        <message>
            <source>Length before (mm)</source>
            <translation>Longueur avant (mm)</translation>
        </message>
        <message>
            <source>Straightness before (mm)</source>
            <translation>Rectitude avant (mm)</translation>
        </message>
        <message>
            <source>Length after (mm)</source>
            <translation>Longueur après (mm)</translation>
        </message>
        <message>
            <source>Straightness after (mm)</source>
            <translation>Rectitude après (mm)</translation>
        </message>
        <message>
            <source>Line %1</source>
            <translation>Ligne %1</translation>
        </message>
        <message>
            <source>Simulation: measure the simulated lines</source>
            <translation>Simulation : mesurer les lignes simulées</translation>
        </message>
        <message>
            <source>Fills the table with the lines as the simulated imperfect machine draws them: before with the profile the wizard started from, after with the calibrated profile.</source>
            <translation>Remplit le tableau avec les lignes telles que la machine simulée imparfaite les trace : avant avec le profil de départ de l'assistant, après avec le profil étalonné.</translation>
        </message>
        <message>
            <source>Line %1, %2: '%3' is not a length in mm.</source>
            <translation>Ligne %1, %2 : « %3 » n'est pas une longueur en mm.</translation>
        </message>
        <message>
            <source>&lt;b&gt;%1:&lt;/b&gt; not measured yet (type a length and a straightness per line).</source>
            <translation>&lt;b&gt;%1 :&lt;/b&gt; pas encore mesuré (saisissez une longueur et une rectitude par ligne).</translation>
        </message>
        <message>
            <source>&lt;b&gt;%1:&lt;/b&gt; straightness %2 mm at worst (RMS %3 mm); length off by %4 mm at worst (RMS %5 mm), over %6 lines.</source>
            <translation>&lt;b&gt;%1 :&lt;/b&gt; rectitude %2 mm au pire (RMS %3 mm) ; longueur décalée de %4 mm au pire (RMS %5 mm), sur %6 lignes.</translation>
        </message>
        <message>
            <source>Before calibration</source>
            <translation>Avant l'étalonnage</translation>
        </message>
        <message>
            <source>After calibration</source>
            <translation>Après l'étalonnage</translation>
        </message>
        <message>
            <source>&lt;br&gt;Worst straightness plus worst length error: %1 mm &amp;rarr; &lt;b&gt;%2 mm&lt;/b&gt;.</source>
            <translation>&lt;br&gt;Pire rectitude plus pire erreur de longueur : %1 mm &amp;rarr; &lt;b&gt;%2 mm&lt;/b&gt;.</translation>
        </message>
        <message>
            <source>&lt;br&gt;&lt;i&gt;Apply the calibration (step 5) to see the lines drawn after it.&lt;/i&gt;</source>
            <translation>&lt;br&gt;&lt;i&gt;Appliquez l'étalonnage (étape 5) pour voir les lignes tracées après.&lt;/i&gt;</translation>
        </message>
        <message>
            <source>Import scan...</source>
            <translation>Importer une numérisation...</translation>
        </message>
        <message>
            <source>A scan of the sheet with the accuracy lines (PNG or JPEG, taken straight from above): each line's length and straightness are measured in the image and fill the columns of the chosen sheet.</source>
            <translation>Une numérisation de la feuille avec les lignes de précision (PNG ou JPEG, pris bien à la verticale) : la longueur et la rectitude de chaque ligne sont mesurées dans l'image et remplissent les colonnes de la feuille choisie.</translation>
        </message>
        <message>
            <source>Sheet drawn before calibration</source>
            <translation>Feuille tracée avant l'étalonnage</translation>
        </message>
        <message>
            <source>Sheet drawn after calibration</source>
            <translation>Feuille tracée après l'étalonnage</translation>
        </message>
        <message>
            <source> dpi</source>
            <translation> dpi</translation>
        </message>
        <message>
            <source>The scanner's resolution: the scan's size in mm comes from it.</source>
            <translation>La résolution du scanner : la taille de la numérisation en mm en découle.</translation>
        </message>
        <message>
            <source>Import a scan of the accuracy lines</source>
            <translation>Importer une numérisation des lignes de précision</translation>
        </message>
        <message>
            <source>Images (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)</source>
            <translation>Images (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)</translation>
        </message>
        <message>
            <source>A line in the scan is too short to measure.</source>
            <translation>Une ligne de la numérisation est trop courte pour être mesurée.</translation>
        </message>
        <message>
            <source>Found %1 lines in the scan (%2 mm pen): the %3 columns are filled.</source>
            <translation>%1 lignes trouvées dans la numérisation (stylo de %2 mm) : les colonnes « %3 » sont remplies.</translation>
        </message>
        <message>
            <source>after</source>
            <translation>après</translation>
        </message>
        <message>
            <source>before</source>
            <translation>avant</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::ApplyPage</name>
        <message>
            <source>5. Apply the calibration to the profile</source>
            <translation>5. Appliquer l'étalonnage au profil</translation>
        </message>
        <message>
            <source>Applying writes the fitted link lengths into the profile and keeps the motor zeros and the backlash in its calibration section. From then on every plan, jog and check uses them. &lt;b&gt;Edit &amp;gt; Undo&lt;/b&gt; takes it back; the profile is saved with the project, and you can also save it as a profile file for other projects.</source>
            <translation>L'application écrit les longueurs de bras ajustées dans le profil et conserve les zéros moteur et le jeu dans sa section d'étalonnage. Dès lors, chaque plan, déplacement manuel et vérification les utilise. &lt;b&gt;Édition &amp;gt; Annuler&lt;/b&gt; revient en arrière ; le profil est enregistré avec le projet, et vous pouvez aussi l'enregistrer comme fichier de profil pour d'autres projets.</translation>
        </message>
        <message>
            <source>Apply to the profile</source>
            <translation>Appliquer au profil</translation>
        </message>
        <message>
            <source>Save profile as...</source>
            <translation>Enregistrer le profil sous...</translation>
        </message>
        <message>
            <source>Save the calibrated profile</source>
            <translation>Enregistrer le profil étalonné</translation>
        </message>
        <message>
            <source>Machine profile (*.json)</source>
            <translation>Profil machine (*.json)</translation>
        </message>
        <message>
            <source>Saved %1.</source>
            <translation>%1 enregistré.</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>°</source>
            <translation>°</translation>
        </message>
        <message>
            <source>motor 1 zero</source>
            <translation>zéro moteur 1</translation>
        </message>
        <message>
            <source>motor 2 zero</source>
            <translation>zéro moteur 2</translation>
        </message>
        <message>
            <source>motor 1 backlash</source>
            <translation>jeu moteur 1</translation>
        </message>
        <message>
            <source>motor 2 backlash</source>
            <translation>jeu moteur 2</translation>
        </message>
        <message>
            <source>Applied. Edit &gt; Undo restores the profile as it was.</source>
            <translation>Appliqué. Édition &gt; Annuler rétablit le profil tel qu'il était.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::CalibrationPreview</name>
        <message>
            <source>No pattern yet</source>
            <translation>Pas encore de motif</translation>
        </message>
        <message>
            <source>pattern as planned</source>
            <translation>motif prévu</translation>
        </message>
        <message>
            <source>drawn by the pen (simulation)</source>
            <translation>tracé par le stylo (simulation)</translation>
        </message>
        <message>
            <source>measured</source>
            <translation>mesuré</translation>
        </message>
        <message>
            <source>error before</source>
            <translation>erreur avant</translation>
        </message>
        <message>
            <source>error after</source>
            <translation>erreur après</translation>
        </message>
        <message>
            <source>arrows ×%1</source>
            <translation>flèches ×%1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::CalibrationWizard</name>
        <message>
            <source>The pattern is already being drawn.</source>
            <translation>Le motif est déjà en cours de tracé.</translation>
        </message>
        <message>
            <source>Connect a machine (or the simulated machine) in the Machine panel first, and let any running job finish.</source>
            <translation>Connectez d'abord une machine (ou la machine simulée) dans le panneau Machine, et laissez finir toute tâche en cours.</translation>
        </message>
        <message>
            <source>Calibrate the machine</source>
            <translation>Étalonner la machine</translation>
        </message>
        <message>
            <source>&amp;Calibrate...</source>
            <translation>É&amp;talonner...</translation>
        </message>
        <message>
            <source>Measure a drawn pattern and correct the profile's link lengths and motor zeros</source>
            <translation>Mesurer un motif tracé et corriger les longueurs de bras et les zéros moteur du profil</translation>
        </message>
        <message>
            <source>Choose a pattern first.</source>
            <translation>Choisissez d'abord un motif.</translation>
        </message>
        <message>
            <source>The pattern cannot be planned: %1</source>
            <translation>Le motif ne peut pas être planifié : %1</translation>
        </message>
        <message>
            <source>The pattern's G-code cannot be written: %1</source>
            <translation>Le G-code du motif ne peut pas être écrit : %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::DistancesBox</name>
        <message>
            <source>Only a ruler? Measure the distance between the centres of two marks and type both mark numbers and the distance. No corner or direction is needed. Measure long and short pairs across the whole sheet, each mark in several pairs: about four per mark (100 for 25 marks) calibrate as well as coordinates. Use the marks for the fit, not the backlash rows.</source>
            <translation>Seulement une règle ? Mesurez la distance entre les centres de deux repères et saisissez les deux numéros et la distance. Ni coin ni direction ne sont nécessaires. Mesurez des paires longues et courtes sur toute la feuille, chaque repère dans plusieurs paires : environ quatre par repère (100 pour 25 repères) étalonnent aussi bien que des coordonnées. Prenez les repères pour l'ajustement, pas les rangées de jeu.</translation>
        </message>
        <message>
            <source>Mark A</source>
            <translation>Repère A</translation>
        </message>
        <message>
            <source>Mark B</source>
            <translation>Repère B</translation>
        </message>
        <message>
            <source>Distance (mm)</source>
            <translation>Distance (mm)</translation>
        </message>
        <message>
            <source>Add a row</source>
            <translation>Ajouter une ligne</translation>
        </message>
        <message>
            <source>Remove the row</source>
            <translation>Supprimer la ligne</translation>
        </message>
        <message>
            <source>Load distances CSV...</source>
            <translation>Charger un CSV de distances...</translation>
        </message>
        <message>
            <source>A file with the columns id_a,id_b,distance_mm (as fivebar calibrate fit reads it)</source>
            <translation>Un fichier avec les colonnes id_a,id_b,distance_mm (comme fivebar calibrate fit le lit)</translation>
        </message>
        <message>
            <source>Simulation: measure distances on the simulated sheet</source>
            <translation>Simulation : mesurer des distances sur la feuille simulée</translation>
        </message>
        <message>
            <source>Fills the table with distances between where the simulated imperfect machine put the marks, plus ruler noise.</source>
            <translation>Remplit le tableau avec les distances entre les endroits où la machine simulée imparfaite a mis les repères, plus le bruit de la règle.</translation>
        </message>
        <message>
            <source>noise ±</source>
            <translation>bruit ±</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>Load distances</source>
            <translation>Charger des distances</translation>
        </message>
        <message>
            <source>CSV (*.csv)</source>
            <translation>CSV (*.csv)</translation>
        </message>
        <message>
            <source>Filled from the simulated sheet (simulation, not a measurement).</source>
            <translation>Rempli d'après la feuille simulée (simulation, pas une mesure).</translation>
        </message>
        <message>
            <source>mark A</source>
            <translation>repère A</translation>
        </message>
        <message>
            <source>mark B</source>
            <translation>repère B</translation>
        </message>
        <message>
            <source>distance</source>
            <translation>distance</translation>
        </message>
        <message>
            <source>Row %1: %2 is empty.</source>
            <translation>Ligne %1 : %2 est vide.</translation>
        </message>
        <message>
            <source>Row %1, %2: '%3' is not a number.</source>
            <translation>Ligne %1, %2 : « %3 » n'est pas un nombre.</translation>
        </message>
        <message>
            <source>Row %1: there is no mark %2 in the pattern.</source>
            <translation>Ligne %1 : il n'y a pas de repère %2 dans le motif.</translation>
        </message>
        <message>
            <source>Row %1: mark %2 is in a backlash row; measure distances between marks for the fit.</source>
            <translation>Ligne %1 : le repère %2 est dans une rangée de jeu ; mesurez des distances entre repères pour l'ajustement.</translation>
        </message>
        <message>
            <source>Row %1: a distance from mark %2 to itself.</source>
            <translation>Ligne %1 : une distance du repère %2 à lui-même.</translation>
        </message>
        <message>
            <source>Row %1: the distance must be more than 0 mm.</source>
            <translation>Ligne %1 : la distance doit dépasser 0 mm.</translation>
        </message>
        <message>
            <source>%1 holds mark coordinates, not distances: load it in the Coordinates tab.</source>
            <translation>%1 contient des coordonnées de repères, pas des distances : chargez-le dans l'onglet Coordonnées.</translation>
        </message>
        <message>
            <source>%1:%2: the pattern's marks are numbered; '%3' is not a mark number.</source>
            <translation>%1:%2 : les repères du motif sont numérotés ; « %3 » n'est pas un numéro de repère.</translation>
        </message>
        <message>
            <source>Loaded %1 distances from %2.</source>
            <translation>%1 distances chargées depuis %2.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::DrawPage</name>
        <message>
            <source>2. Draw the pattern</source>
            <translation>2. Tracer le motif</translation>
        </message>
        <message>
            <source>Tape a sheet down so it cannot move, and draw the pattern with the pen you normally use. Draw it on the connected machine, or export its G-code and send it your way. Keep MARKS.csv: it says which motor angles drew each mark.</source>
            <translation>Fixez une feuille avec du ruban adhésif pour qu'elle ne bouge pas, et tracez le motif avec le stylo que vous utilisez d'habitude. Tracez-le sur la machine connectée, ou exportez son G-code et envoyez-le à votre façon. Gardez MARKS.csv : il indique quels angles moteur ont tracé chaque repère.</translation>
        </message>
        <message>
            <source>Draw on the connected machine</source>
            <translation>Tracer sur la machine connectée</translation>
        </message>
        <message>
            <source>Export G-code...</source>
            <translation>Exporter le G-code...</translation>
        </message>
        <message>
            <source>Export MARKS.csv...</source>
            <translation>Exporter MARKS.csv...</translation>
        </message>
        <message>
            <source>No hardware? Simulate an imperfect machine</source>
            <translation>Pas de matériel ? Simulez une machine imparfaite</translation>
        </message>
        <message>
            <source>Simulate an imperfect machine (the sheet below is what it draws)</source>
            <translation>Simuler une machine imparfaite (la feuille ci-dessous est ce qu'elle trace)</translation>
        </message>
        <message>
            <source>The pattern is drawn. Take the sheet off and measure it.</source>
            <translation>Le motif est tracé. Retirez la feuille et mesurez-la.</translation>
        </message>
        <message>
            <source>Drawing the pattern (%1 lines of G-code)...</source>
            <translation>Tracé du motif (%1 lignes de G-code)...</translation>
        </message>
        <message>
            <source>Export the pattern's G-code</source>
            <translation>Exporter le G-code du motif</translation>
        </message>
        <message>
            <source>G-code (*.gcode *.nc)</source>
            <translation>G-code (*.gcode *.nc)</translation>
        </message>
        <message>
            <source>Wrote %1.</source>
            <translation>%1 écrit.</translation>
        </message>
        <message>
            <source>Export MARKS.csv</source>
            <translation>Exporter MARKS.csv</translation>
        </message>
        <message>
            <source>CSV (*.csv)</source>
            <translation>CSV (*.csv)</translation>
        </message>
        <message>
            <source>Streams the pattern with the same checks as the Run panel</source>
            <translation>Envoie le motif avec les mêmes vérifications que le panneau Exécution</translation>
        </message>
        <message>
            <source>Connect a machine or the simulated machine in the Machine panel first</source>
            <translation>Connectez d'abord une machine ou la machine simulée dans le panneau Machine</translation>
        </message>
        <message>
            <source>The simulated machine differs from the profile by these amounts, as a real one would. The picture shows what its pen really draws (orange) beside the plan. The built-in simulated machine (Machine panel) becomes this machine at once, also when it is connected. When the wizard closes it goes back to the studio's setting (Machine &amp;gt; Simulated machine...), unless you keep it.</source>
            <translation>La machine simulée diffère du profil de ces valeurs, comme le ferait une vraie. L'image montre ce que son stylo trace vraiment (orange) à côté du plan. La machine simulée intégrée (panneau Machine) devient aussitôt cette machine, même connectée. À la fermeture de l'assistant, le réglage du studio revient (Machine &amp;gt; Machine simulée...), sauf si vous la gardez.</translation>
        </message>
        <message>
            <source>Keep this machine as the studio's simulated machine after the wizard</source>
            <translation>Garder cette machine comme machine simulée du studio après l'assistant</translation>
        </message>
        <message>
            <source>Saved in Machine &gt; Simulated machine...; the status bar shows it while it is imperfect</source>
            <translation>Enregistrée dans Machine &gt; Machine simulée... ; la barre d'état l'affiche tant qu'elle est imparfaite</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::FitPage</name>
        <message>
            <source>4. Fit the machine to the marks</source>
            <translation>4. Ajuster la machine aux repères</translation>
        </message>
        <message>
            <source>The fit looks for the link lengths and motor zeros with which the machine would have put every mark where you measured it. Some marks are kept out of the fit and only used to check it afterwards ("held out"): their error is the honest one. The arrows show each mark's error, greatly enlarged: grey before, red after.</source>
            <translation>L'ajustement cherche les longueurs de bras et les zéros moteur avec lesquels la machine aurait placé chaque repère là où vous l'avez mesuré. Certains repères sont exclus de l'ajustement et servent seulement à le vérifier ensuite (« réservés ») : leur erreur est la plus honnête. Les flèches montrent l'erreur de chaque repère, fortement agrandie : gris avant, rouge après.</translation>
        </message>
        <message>
            <source>Parameter</source>
            <translation>Paramètre</translation>
        </message>
        <message>
            <source>Profile</source>
            <translation>Profil</translation>
        </message>
        <message>
            <source>Fitted ± std. dev.</source>
            <translation>Ajusté ± écart type</translation>
        </message>
        <message>
            <source>&lt;span style='color:#b00000'&gt;&lt;b&gt;The fit failed:&lt;/b&gt; %1&lt;/span&gt;&lt;br&gt;Go back, check the table, or measure more marks.</source>
            <translation>&lt;span style='color:#b00000'&gt;&lt;b&gt;L'ajustement a échoué :&lt;/b&gt; %1&lt;/span&gt;&lt;br&gt;Revenez en arrière, vérifiez le tableau ou mesurez plus de repères.</translation>
        </message>
        <message>
            <source>Backlash from %1 + %2 rows: motor 1 %3°, motor 2 %4°.</source>
            <translation>Jeu d'après %1 + %2 rangées : moteur 1 %3°, moteur 2 %4°.</translation>
        </message>
        <message>
            <source>Backlash not measured: %1</source>
            <translation>Jeu non mesuré : %1</translation>
        </message>
        <message>
            <source>No mark looks mis-measured.</source>
            <translation>Aucun repère ne semble mal mesuré.</translation>
        </message>
        <message>
            <source>&lt;span style='color:#b00000'&gt;Left out as mis-measured: mark %1. Check it on the sheet.&lt;/span&gt;</source>
            <translation>&lt;span style='color:#b00000'&gt;Écarté car mal mesuré : repère %1. Vérifiez-le sur la feuille.&lt;/span&gt;</translation>
        </message>
        <message>
            <source>°</source>
            <translation>°</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>%1 ± %2%3</source>
            <translation>%1 ± %2%3</translation>
        </message>
        <message>
            <source>Backlash is not measured from distances (it needs the positions of the backlash rows' marks); the profile's backlash is kept.</source>
            <translation>Le jeu n'est pas mesuré à partir des distances (il faut les positions des repères des rangées de jeu) ; le jeu du profil est conservé.</translation>
        </message>
        <message>
            <source>&lt;span style='color:#b00000'&gt;Left out as mis-measured: distance %1 (marks A-B). Measure it again.&lt;/span&gt;</source>
            <translation>&lt;span style='color:#b00000'&gt;Écartée comme mal mesurée : distance %1 (repères A-B). Mesurez-la à nouveau.&lt;/span&gt;</translation>
        </message>
        <message>
            <source>&lt;b&gt;Distance error before: %1 mm RMS&lt;/b&gt; (largest %2 mm) &amp;rarr; &lt;b&gt;after: %3 mm RMS&lt;/b&gt; (largest %4 mm) over %5 distances.</source>
            <translation>&lt;b&gt;Erreur de distance avant : %1 mm RMS&lt;/b&gt; (plus grande %2 mm) &amp;rarr; &lt;b&gt;après : %3 mm RMS&lt;/b&gt; (plus grande %4 mm) sur %5 distances.</translation>
        </message>
        <message>
            <source>&lt;b&gt;Error before: %1 mm RMS&lt;/b&gt; (largest %2 mm) &amp;rarr; &lt;b&gt;after: %3 mm RMS&lt;/b&gt; (largest %4 mm) over %5 marks.</source>
            <translation>&lt;b&gt;Erreur avant : %1 mm RMS&lt;/b&gt; (plus grande %2 mm) &amp;rarr; &lt;b&gt;après : %3 mm RMS&lt;/b&gt; (plus grande %4 mm) sur %5 repères.</translation>
        </message>
        <message>
            <source>&lt;br&gt;Held-out measurements (%1): %2 mm before &amp;rarr; %3 mm after.&lt;br&gt;%4&lt;br&gt;%5&lt;br&gt;&lt;small&gt;Condition number %6 (below 10000 is fine).&lt;/small&gt;</source>
            <translation>&lt;br&gt;Mesures mises de côté (%1) : %2 mm avant &amp;rarr; %3 mm après.&lt;br&gt;%4&lt;br&gt;%5&lt;br&gt;&lt;small&gt;Conditionnement %6 (sous 10000, c'est bien).&lt;/small&gt;</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::MeasurePage</name>
        <message>
            <source>3. Measure the marks</source>
            <translation>3. Mesurer les repères</translation>
        </message>
        <message>
            <source>Mark</source>
            <translation>Repère</translation>
        </message>
        <message>
            <source>Kind</source>
            <translation>Type</translation>
        </message>
        <message>
            <source>x (mm)</source>
            <translation>x (mm)</translation>
        </message>
        <message>
            <source>y (mm)</source>
            <translation>y (mm)</translation>
        </message>
        <message>
            <source>Simulation: measure the simulated sheet</source>
            <translation>Simulation : mesurer la feuille simulée</translation>
        </message>
        <message>
            <source>Fills the table with where the simulated imperfect machine put each mark, plus ruler noise. For trying the wizard without hardware.</source>
            <translation>Remplit le tableau avec les positions où la machine imparfaite simulée a placé chaque repère, plus un bruit de règle. Pour essayer l'assistant sans matériel.</translation>
        </message>
        <message>
            <source>noise ±</source>
            <translation>bruit ±</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>Import a scan...</source>
            <translation>Importer une numérisation...</translation>
        </message>
        <message>
            <source>A scan or photo taken straight from above (PNG or JPEG): the marks are found and numbered by themselves.</source>
            <translation>Une numérisation ou une photo prise bien à la verticale (PNG ou JPEG) : les repères sont trouvés et numérotés automatiquement.</translation>
        </message>
        <message>
            <source> dpi</source>
            <translation> dpi</translation>
        </message>
        <message>
            <source>The scanner's resolution: the scan's size in mm comes from it.</source>
            <translation>La résolution du scanner : la taille de la numérisation en mm en découle.</translation>
        </message>
        <message>
            <source>Load MEASURED.csv...</source>
            <translation>Charger MEASURED.csv...</translation>
        </message>
        <message>
            <source>Save MEASURED.csv...</source>
            <translation>Enregistrer MEASURED.csv...</translation>
        </message>
        <message>
            <source>Import a scan of the sheet</source>
            <translation>Importer une numérisation de la feuille</translation>
        </message>
        <message>
            <source>Images (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)</source>
            <translation>Images (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)</translation>
        </message>
        <message>
            <source>Load MEASURED.csv</source>
            <translation>Charger MEASURED.csv</translation>
        </message>
        <message>
            <source>CSV (*.csv)</source>
            <translation>CSV (*.csv)</translation>
        </message>
        <message>
            <source>Save MEASURED.csv</source>
            <translation>Enregistrer MEASURED.csv</translation>
        </message>
        <message>
            <source>fit</source>
            <translation>ajustement</translation>
        </message>
        <message>
            <source>backlash %1</source>
            <translation>jeu %1</translation>
        </message>
        <message>
            <source>Filled from the simulated sheet (simulation, not a measurement).</source>
            <translation>Rempli d'après la feuille simulée (simulation, pas une mesure).</translation>
        </message>
        <message>
            <source>Mark %1: %2 is empty. Type both x and y, or leave both empty.</source>
            <translation>Repère %1 : %2 est vide. Saisissez x et y, ou laissez les deux vides.</translation>
        </message>
        <message>
            <source>Mark %1, %2: '%3' is not a number.</source>
            <translation>Repère %1, %2 : '%3' n'est pas un nombre.</translation>
        </message>
        <message>
            <source>Only %1 marks for the fit are measured; measure at least %2 (the fit finds 5 lengths, 2 motor zeros and how the sheet lay).</source>
            <translation>Seuls %1 repères pour l'ajustement sont mesurés ; mesurez-en au moins %2 (l'ajustement trouve 5 longueurs, 2 zéros moteur et la position de la feuille).</translation>
        </message>
        <message>
            <source>Cannot read %1: %2</source>
            <translation>Impossible de lire %1 : %2</translation>
        </message>
        <message>
            <source>Found %1 of %2 marks in the scan (sheet turned %3°%4).%5</source>
            <translation>%1 repères sur %2 trouvés dans la numérisation (feuille tournée de %3°%4).%5</translation>
        </message>
        <message>
            <source>, mirrored</source>
            <translation>, en miroir</translation>
        </message>
        <message>
            <source> Not found: %1; type them in by hand.</source>
            <translation> Non trouvés : %1 ; saisissez-les à la main.</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>Impossible d'écrire %1 : %2</translation>
        </message>
        <message>
            <source>Measure the centre of each numbered dot with a ruler and type its x and y in millimetres. Any corner of the sheet can be the origin, and y may point up or down: the fit finds how the sheet lay. The mark you are typing is circled on the picture. Leave a row empty if a mark cannot be read; a mis-measured mark is found and named by the fit. With a scanner, import a scan instead: the marks are found and numbered for you. With a ruler alone, measure distances between marks in the second tab.</source>
            <translation>Mesurez le centre de chaque point numéroté avec une règle et saisissez ses x et y en millimètres. N'importe quel coin de la feuille peut être l'origine, et y peut pointer vers le haut ou le bas : l'ajustement trouve comment la feuille était posée. Le repère en cours de saisie est entouré sur l'image. Laissez une ligne vide si un repère est illisible ; un repère mal mesuré est trouvé et nommé par l'ajustement. Avec un scanner, importez plutôt un scan : les repères sont trouvés et numérotés pour vous. Avec une règle seule, mesurez des distances entre repères dans le second onglet.</translation>
        </message>
        <message>
            <source>Coordinates (x, y)</source>
            <translation>Coordonnées (x, y)</translation>
        </message>
        <message>
            <source>Distances between marks</source>
            <translation>Distances entre repères</translation>
        </message>
        <message>
            <source>Only %1 distances are measured; measure at least %2, about four for each mark (the fit finds 5 lengths and 2 motor zeros).</source>
            <translation>Seulement %1 distances sont mesurées ; mesurez-en au moins %2, environ quatre par repère (l'ajustement trouve 5 longueurs et 2 zéros moteur).</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::PatternPage</name>
        <message>
            <source>1. Choose the pattern</source>
            <translation>1. Choisir le motif</translation>
        </message>
        <message>
            <source>Calibration marks</source>
            <translation>Repères d'étalonnage</translation>
        </message>
        <message>
            <source>Accuracy pattern only (10 lines)</source>
            <translation>Motif de précision seul (10 lignes)</translation>
        </message>
        <message>
            <source> marks</source>
            <translation> repères</translation>
        </message>
        <message>
            <source>More marks: a more certain fit, more to measure. 25 is a good start.</source>
            <translation>Plus de repères : un ajustement plus sûr, plus à mesurer. 25 est un bon début.</translation>
        </message>
        <message>
            <source>Marks for the fit:</source>
            <translation>Repères pour l'ajustement :</translation>
        </message>
        <message>
            <source>&lt;span style='color:#b00000'&gt;%1&lt;/span&gt;</source>
            <translation>&lt;span style='color:#b00000'&gt;%1&lt;/span&gt;</translation>
        </message>
        <message>
            <source>For &lt;b&gt;%1&lt;/b&gt;: %2 marks for the fit and %3 marks in backlash rows%4.</source>
            <translation>Pour &lt;b&gt;%1&lt;/b&gt; : %2 repères pour l'ajustement et %3 repères en rangées de jeu%4.</translation>
        </message>
        <message>
            <source>, with the accuracy lines in the middle</source>
            <translation>, avec les lignes de précision au milieu</translation>
        </message>
        <message>
            <source>For &lt;b&gt;%1&lt;/b&gt;: ten lines of 40 mm in the middle of the working area.</source>
            <translation>Pour &lt;b&gt;%1&lt;/b&gt; : dix lignes de 40 mm au milieu de la zone de travail.</translation>
        </message>
        <message>
            <source>No machine is built exactly as drawn: a link cut half a millimetre long or a motor zero set by eye bends every drawing. The studio draws a &lt;b&gt;pattern&lt;/b&gt; of numbered marks, you measure where they really landed, and a fit finds the machine's true link lengths and motor zeros.&lt;br&gt;&lt;br&gt;&lt;b&gt;Calibration marks&lt;/b&gt;: numbered dots in rings spread over the whole working area, plus rows that show the slack (backlash) of each motor. Use these to calibrate.&lt;br&gt;&lt;b&gt;Accuracy pattern&lt;/b&gt; (Hoang): ten parallel lines, 40 mm long and 10 mm apart, to judge straightness and length before and after: you measure each line's length and straightness with a ruler in the wizard's last step.</source>
            <translation>Aucune machine n'est construite exactement comme dessinée : un bras coupé un demi-millimètre trop long ou un zéro moteur réglé à l'œil déforme chaque dessin. Le studio trace un &lt;b&gt;motif&lt;/b&gt; de repères numérotés, vous mesurez où ils sont vraiment tombés, et un ajustement trouve les vraies longueurs des bras et les zéros des moteurs.&lt;br&gt;&lt;br&gt;&lt;b&gt;Repères d'étalonnage&lt;/b&gt; : des points numérotés dans des anneaux répartis sur toute la zone de travail, plus des rangées qui montrent le jeu de chaque moteur. À utiliser pour étalonner.&lt;br&gt;&lt;b&gt;Motif de précision&lt;/b&gt; (Hoang) : dix lignes parallèles, longues de 40 mm et espacées de 10 mm, pour juger la rectitude et la longueur avant et après : vous mesurez la longueur et la rectitude de chaque ligne avec une règle à la dernière étape de l'assistant.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SheetLayer</name>
        <message>
            <source>Calibration pattern (plan)</source>
            <translation>Motif d'étalonnage (plan)</translation>
        </message>
        <message>
            <source>Drawn by the pen (simulated imperfect machine)</source>
            <translation>Tracé par le stylo (machine imparfaite simulée)</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SimTraceLayer</name>
        <message>
            <source>Drawn by the simulated pen (imperfect machine)</source>
            <translation>Tracé par le stylo simulé (machine imparfaite)</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SimulatedMachineDialog</name>
        <message>
            <source>Simulated machine</source>
            <translation>Machine simulée</translation>
        </message>
        <message>
            <source>The built-in simulated machine can be built &lt;b&gt;imperfectly&lt;/b&gt;, as a real one is: its links a little longer or shorter than the profile says, its motor zeros off, play in its drives. It then draws what such a machine really draws (shown on the canvas beside the plan), so you can try calibration (Machine &amp;gt; Calibrate...) without hardware.&lt;br&gt;&lt;br&gt;The amounts apply at once, also to a simulated machine that is connected, and are kept until you change them here. The status bar says so while the machine is imperfect.</source>
            <translation>La machine simulée intégrée peut être construite &lt;b&gt;imparfaitement&lt;/b&gt;, comme une vraie : ses bras un peu plus longs ou plus courts que ne le dit le profil, ses zéros moteur décalés, du jeu dans ses entraînements. Elle trace alors ce qu'une telle machine trace vraiment (affiché sur le canevas à côté du plan), pour essayer l'étalonnage (Machine &amp;gt; Étalonner...) sans matériel.&lt;br&gt;&lt;br&gt;Les valeurs s'appliquent aussitôt, aussi à une machine simulée connectée, et restent jusqu'à ce que vous les changiez ici. La barre d'état l'indique tant que la machine est imparfaite.</translation>
        </message>
        <message>
            <source>Perfect machine</source>
            <translation>Machine parfaite</translation>
        </message>
        <message>
            <source>All amounts zero: the simulated machine is exactly the profile</source>
            <translation>Toutes les valeurs à zéro : la machine simulée est exactement le profil</translation>
        </message>
        <message>
            <source>Example</source>
            <translation>Exemple</translation>
        </message>
        <message>
            <source>A typical home-built machine: links off by up to 0.5 mm, zeros by about 1°, some play</source>
            <translation>Une machine typique faite maison : bras décalés jusqu'à 0,5 mm, zéros d'environ 1°, un peu de jeu</translation>
        </message>
        <message>
            <source>Simulated &amp;machine...</source>
            <translation>&amp;Machine simulée...</translation>
        </message>
        <message>
            <source>Build the simulated machine imperfectly, to try calibration without hardware</source>
            <translation>Construire la machine simulée imparfaite, pour essayer l'étalonnage sans matériel</translation>
        </message>
        <message>
            <source>OK</source>
            <translation>OK</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Annuler</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SimulatedTruth</name>
        <message>
            <source>%1 %2 mm</source>
            <translation>%1 %2 mm</translation>
        </message>
        <message>
            <source>motor %1 zero %2°</source>
            <translation>zéro du moteur %1 %2°</translation>
        </message>
        <message>
            <source>motor %1 backlash %2°</source>
            <translation>jeu du moteur %1 %2°</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SimulatedTruthBadge</name>
        <message>
            <source>Simulated machine: imperfect</source>
            <translation>Machine simulée : imparfaite</translation>
        </message>
        <message>
            <source>The built-in simulated machine differs from the profile: %1. Click to change it (Machine &gt; Simulated machine...).</source>
            <translation>La machine simulée intégrée diffère du profil : %1. Cliquer pour la modifier (Machine &gt; Machine simulée...).</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::TrueMachineForm</name>
        <message>
            <source>How much longer the real part is than the profile says (negative: shorter).</source>
            <translation>De combien la pièce réelle est plus longue que ne le dit le profil (négatif : plus courte).</translation>
        </message>
        <message>
            <source>a1 longer by</source>
            <translation>a1 plus long de</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>b1 longer by</source>
            <translation>b1 plus long de</translation>
        </message>
        <message>
            <source>a2 longer by</source>
            <translation>a2 plus long de</translation>
        </message>
        <message>
            <source>b2 longer by</source>
            <translation>b2 plus long de</translation>
        </message>
        <message>
            <source>motors farther apart by</source>
            <translation>moteurs plus écartés de</translation>
        </message>
        <message>
            <source>How much farther apart the real motor axes are.</source>
            <translation>De combien les axes réels des moteurs sont plus éloignés.</translation>
        </message>
        <message>
            <source>motor 1 zero off by</source>
            <translation>zéro moteur 1 décalé de</translation>
        </message>
        <message>
            <source> °</source>
            <translation> °</translation>
        </message>
        <message>
            <source>The real arm angle is the commanded one plus this.</source>
            <translation>L'angle réel du bras est l'angle commandé plus cette valeur.</translation>
        </message>
        <message>
            <source>motor 2 zero off by</source>
            <translation>zéro moteur 2 décalé de</translation>
        </message>
        <message>
            <source>motor 1 backlash</source>
            <translation>jeu moteur 1</translation>
        </message>
        <message>
            <source>Play in the drive: the arm lags this much when the motor reverses.</source>
            <translation>Jeu dans l'entraînement : le bras est en retard d'autant quand le moteur change de sens.</translation>
        </message>
        <message>
            <source>motor 2 backlash</source>
            <translation>jeu moteur 2</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::VerifyPage</name>
        <message>
            <source>6. Draw the verification pattern</source>
            <translation>6. Tracer le motif de vérification</translation>
        </message>
        <message>
            <source>Draw on the connected machine</source>
            <translation>Tracer sur la machine connectée</translation>
        </message>
        <message>
            <source>Export G-code...</source>
            <translation>Exporter le G-code...</translation>
        </message>
        <message>
            <source>The verification pattern is drawn.</source>
            <translation>Le motif de vérification est tracé.</translation>
        </message>
        <message>
            <source>Drawing the verification pattern...</source>
            <translation>Tracé du motif de vérification...</translation>
        </message>
        <message>
            <source>Export the verification G-code</source>
            <translation>Exporter le G-code de vérification</translation>
        </message>
        <message>
            <source>G-code (*.gcode *.nc)</source>
            <translation>G-code (*.gcode *.nc)</translation>
        </message>
        <message>
            <source>Wrote %1.</source>
            <translation>%1 écrit.</translation>
        </message>
        <message>
            <source>Cannot write %1.</source>
            <translation>Impossible d'écrire %1.</translation>
        </message>
        <message>
            <source>&lt;b&gt;Simulation:&lt;/b&gt; the imperfect machine puts the marks %1 mm RMS (largest %2 mm) from where they are meant with the old profile, and &lt;b&gt;%3 mm RMS (largest %4 mm)&lt;/b&gt; with the profile now in use%5.</source>
            <translation>&lt;b&gt;Simulation :&lt;/b&gt; avec l'ancien profil, la machine imparfaite place les repères à %1 mm RMS (max. %2 mm) de leur position prévue, et à &lt;b&gt;%3 mm RMS (max. %4 mm)&lt;/b&gt; avec le profil actuel%5.</translation>
        </message>
        <message>
            <source> (the calibration is not applied)</source>
            <translation> (l'étalonnage n'est pas appliqué)</translation>
        </message>
        <message>
            <source>Draw the pattern once more, now planned with the calibrated profile, on a fresh sheet. Its marks should land where they were meant, and the accuracy lines should be straight and 40 mm long: &lt;b&gt;Next&lt;/b&gt; measures the lines with a ruler for a before/after figure.</source>
            <translation>Tracez le motif une fois de plus, maintenant planifié avec le profil étalonné, sur une feuille neuve. Ses repères devraient tomber là où ils sont prévus, et les lignes de précision devraient être droites et longues de 40 mm : &lt;b&gt;Suivant&lt;/b&gt; mesure les lignes à la règle pour un chiffre avant/après.</translation>
        </message>
    </context>
    <context>
        <name>main</name>
        <message>
            <source>Plan and simulate drawings for five-bar robots.</source>
            <translation>Planifier et simuler des dessins pour robots à cinq barres.</translation>
        </message>
        <message>
            <source>Open the demo drawing on the default maker plotter.</source>
            <translation>Ouvrir le dessin de démonstration sur le traceur maker par défaut.</translation>
        </message>
        <message>
            <source>Save a picture of the window once the job is planned, then quit.</source>
            <translation>Enregistrer une image de la fenêtre une fois la tâche planifiée, puis quitter.</translation>
        </message>
        <message>
            <source>With --screenshot: show the workspace legend (legend) or a map (transmission, conditioning or resolution).</source>
            <translation>Avec --screenshot : afficher la légende de l'espace de travail (legend) ou une carte (transmission, conditioning ou resolution).</translation>
        </message>
        <message>
            <source>With --screenshot: simulation position as a fraction of the job (0 to 1).</source>
            <translation>Avec --screenshot : position de la simulation en fraction de la tâche (0 à 1).</translation>
        </message>
        <message>
            <source>Print how long opening and planning the drawing took, stage by stage, to stderr (as fivebar plan --timings).</source>
            <translation>Afficher sur stderr la durée de l’ouverture et de la planification du dessin, étape par étape (comme fivebar plan --timings).</translation>
        </message>
        <message>
            <source>Machine profile: a preset name or a profile JSON file (default: the last one used, else maker-plotter).</source>
            <translation>Profil de machine : un nom de préréglage ou un fichier de profil JSON (par défaut : le dernier utilisé, sinon maker-plotter).</translation>
        </message>
        <message>
            <source>Plan the drawing or project as the studio does, write the G-code and exit (no window).</source>
            <translation>Planifier le dessin ou le projet comme le fait le studio, écrire le G-code et quitter (sans fenêtre).</translation>
        </message>
        <message>
            <source>SVG drawing or project to open.</source>
            <translation>Dessin SVG ou projet à ouvrir.</translation>
        </message>
        <message>
            <source>Filled shapes: outline (default), hatch or none; with hatch: SPACING_MM and ANGLE_DEG after colons.</source>
            <translation>Formes remplies : outline (par défaut), hatch ou none ; avec hatch : SPACING_MM et ANGLE_DEG après des deux-points.</translation>
        </message>
        <message>
            <source>User interface language: de, en, es or fr (default: View &gt; Language, else the system's).</source>
            <translation>Langue de l'interface : de, en, es ou fr (par défaut : Affichage &gt; Langue, sinon celle du système).</translation>
        </message>
        <message>
            <source>Connect to the board on this port at start, as the Connect button does: a serial device, a pseudo-terminal or tcp:HOST:PORT.</source>
            <translation>Se connecter au démarrage à la carte sur ce port, comme le fait le bouton Connecter : un périphérique série, un pseudo-terminal ou tcp:HOST:PORT.</translation>
        </message>
        <message>
            <source>With --port: the baud rate (default: the machine profile's, usually 115200).</source>
            <translation>Avec --port : le débit en bauds (par défaut : celui du profil de machine, souvent 115200).</translation>
        </message>
    </context>
    <context>
        <name>Profile</name>
        <message>
            <source>deg</source>
            <translation>°</translation>
        </message>
        <message>
            <source>%1 must be a finite number of millimetres</source>
            <translation>%1 doit être un nombre fini de millimètres</translation>
        </message>
        <message>
            <source>%1 is %2 mm; it must be zero or positive</source>
            <translation>%1 vaut %2 mm ; la valeur doit être nulle ou positive</translation>
        </message>
        <message>
            <source>%1 is %2 mm; it must be positive</source>
            <translation>%1 vaut %2 mm ; la valeur doit être positive</translation>
        </message>
        <message>
            <source>the legs can never meet: a1+b1 + a2+b2 = %1 mm is less than w = %2 mm</source>
            <translation>les bras ne peuvent jamais se rejoindre : a1+b1 + a2+b2 = %1 mm est inférieur à w = %2 mm</translation>
        </message>
        <message>
            <source>the legs can never meet: one leg's dead zone |a-b| encloses the other leg's whole reach</source>
            <translation>les bras ne peuvent jamais se rejoindre : la zone morte |a-b| d'un bras englobe toute la portée de l'autre</translation>
        </message>
        <message>
            <source>%1 limits must be finite numbers of degrees</source>
            <translation>les limites de %1 doivent être des nombres finis de degrés</translation>
        </message>
        <message>
            <source>%1 minimum %2 deg is not below its maximum %3 deg, so no pose is allowed</source>
            <translation>le minimum de %1 (%2°) n'est pas inférieur à son maximum (%3°) : aucune position n'est permise</translation>
        </message>
        <message>
            <source>the joint limits exclude every pose in which the linkage closes</source>
            <translation>les limites articulaires excluent toutes les positions où le mécanisme se referme</translation>
        </message>
        <message>
            <source>calibration.version %1 is not supported; this program reads version %2</source>
            <translation>calibration.version %1 n'est pas prise en charge ; ce programme lit la version %2</translation>
        </message>
        <message>
            <source>calibration.date must be an ISO 8601 date like 2026-12-01 or 2026-12-01T22:30:00Z, got "%1"</source>
            <translation>calibration.date doit être une date ISO 8601 comme 2026-12-01 ou 2026-12-01T22:30:00Z, et non « %1 »</translation>
        </message>
        <message>
            <source>calibration.outliers[%1] must be a mark id, got an empty string</source>
            <translation>calibration.outliers[%1] doit être un identifiant de marque, et non une chaîne vide</translation>
        </message>
        <message>
            <source>%1 must be a finite number</source>
            <translation>%1 doit être un nombre fini</translation>
        </message>
        <message>
            <source>%1 (%2) must be below %3 (%4)</source>
            <translation>%1 (%2) doit être inférieur à %3 (%4)</translation>
        </message>
        <message>
            <source>tool.zUpMm (%1) must be above tool.zDownMm (%2)</source>
            <translation>tool.zUpMm (%1) doit être supérieur à tool.zDownMm (%2)</translation>
        </message>
        <message>
            <source>%1 (%2) lies outside the joint limits [%3, %4]</source>
            <translation>%1 (%2) est hors des limites articulaires [%3 ; %4]</translation>
        </message>
        <message>
            <source>name must not be empty</source>
            <translation>name ne doit pas être vide</translation>
        </message>
        <message>
            <source>workingMode must be one of ++, +-, -+, --, got "%1"</source>
            <translation>workingMode doit valoir ++, +-, -+ ou --, et non « %1 »</translation>
        </message>
        <message>
            <source>assemblyMode must be + or -, got "%1"</source>
            <translation>assemblyMode doit valoir + ou -, et non « %1 »</translation>
        </message>
        <message>
            <source>tool.kind must be pen-servo, z-axis or laser, got "%1"</source>
            <translation>tool.kind doit valoir pen-servo, z-axis ou laser, et non « %1 »</translation>
        </message>
        <message>
            <source>schema must be "%1", got "%2" (is this a machine profile?)</source>
            <translation>schema doit valoir « %1 », et non « %2 » (est-ce bien un profil de machine ?)</translation>
        </message>
        <message>
            <source>version %1 is not supported; this program reads version %2</source>
            <translation>la version %1 n'est pas prise en charge ; ce programme lit la version %2</translation>
        </message>
        <message>
            <source>%1:%2:%3: invalid JSON: %4</source>
            <translation>%1:%2:%3 : JSON invalide : %4</translation>
        </message>
        <message>
            <source>the profile must be a JSON object ({...})</source>
            <translation>le profil doit être un objet JSON ({...})</translation>
        </message>
        <message>
            <source>%1 must be positive, got %2</source>
            <translation>%1 doit être positif, et non %2</translation>
        </message>
        <message>
            <source>%1 must be zero or positive, got %2</source>
            <translation>%1 doit être nul ou positif, et non %2</translation>
        </message>
        <message>
            <source>%1 must be between %2 and %3 %4, got %5</source>
            <translation>%1 doit être compris entre %2 et %3 %4, et non %5</translation>
        </message>
        <message>
            <source>%1 must be between %2 and %3, got %4</source>
            <translation>%1 doit être compris entre %2 et %3, et non %4</translation>
        </message>
        <message>
            <source>cannot open %1: %2</source>
            <translation>impossible d'ouvrir %1 : %2</translation>
        </message>
        <message>
            <source>unknown machine preset '%1' (presets: %2; or give a profile file path)</source>
            <translation>préréglage de machine inconnu « %1 » (préréglages : %2 ; ou indiquez le chemin d'un fichier de profil)</translation>
        </message>
        <message>
            <source>a number</source>
            <translation>un nombre</translation>
        </message>
        <message>
            <source>a string</source>
            <translation>une chaîne</translation>
        </message>
        <message>
            <source>a boolean</source>
            <translation>un booléen</translation>
        </message>
        <message>
            <source>an object</source>
            <translation>un objet</translation>
        </message>
        <message>
            <source>an array</source>
            <translation>un tableau</translation>
        </message>
        <message>
            <source>null</source>
            <translation>null</translation>
        </message>
        <message>
            <source>an unsupported value</source>
            <translation>une valeur non prise en charge</translation>
        </message>
        <message>
            <source>%1 is missing (it is required)</source>
            <translation>%1 est absent (ce champ est obligatoire)</translation>
        </message>
        <message>
            <source>%1 must be %2, got %3 "%4"</source>
            <translation>%1 doit être %2, et non %3 « %4 »</translation>
        </message>
        <message>
            <source>%1 must be %2, got %3</source>
            <translation>%1 doit être %2, et non %3</translation>
        </message>
        <message>
            <source>an integer</source>
            <translation>un entier</translation>
        </message>
        <message>
            <source>%1 is out of the integer range</source>
            <translation>%1 dépasse la plage des entiers</translation>
        </message>
        <message>
            <source>true or false</source>
            <translation>true ou false</translation>
        </message>
        <message>
            <source>an array of strings</source>
            <translation>un tableau de chaînes</translation>
        </message>
        <message>
            <source>%1 must be a string, got %2</source>
            <translation>%1 doit être une chaîne, et non %2</translation>
        </message>
        <message>
            <source>%1 is not a known field (expected one of: %2)</source>
            <translation>%1 n'est pas un champ connu (attendu : l'un de %2)</translation>
        </message>
        <message>
            <source>machine: %1</source>
            <translation>machine : %1</translation>
        </message>
    </context>
    <context>
        <name>CalibrationFile</name>
        <message>
            <source>%1: header must be '%2'</source>
            <translation>%1 : l'en-tête doit être « %2 »</translation>
        </message>
        <message>
            <source>%1: %2 fields, expected %3</source>
            <translation>%1 : %2 champs, %3 attendus</translation>
        </message>
        <message>
            <source>%1: empty file (expected the header '%2')</source>
            <translation>%1 : fichier vide (en-tête « %2 » attendu)</translation>
        </message>
        <message>
            <source>%1: %2: '%3' is not a number</source>
            <translation>%1 : %2 : « %3 » n'est pas un nombre</translation>
        </message>
        <message>
            <source>%1: cannot open the file</source>
            <translation>%1 : impossible d'ouvrir le fichier</translation>
        </message>
        <message>
            <source>%1: id: '%2' is not a positive integer</source>
            <translation>%1 : id : « %2 » n'est pas un entier positif</translation>
        </message>
        <message>
            <source>%1: id: duplicate id %2</source>
            <translation>%1 : id : identifiant %2 en double</translation>
        </message>
        <message>
            <source>%1: kind: '%2' is not grid or backlash</source>
            <translation>%1 : kind : « %2 » n'est ni grid ni backlash</translation>
        </message>
        <message>
            <source>%1: %2: '%3' is not + or -</source>
            <translation>%1 : %2 : « %3 » n'est ni + ni -</translation>
        </message>
        <message>
            <source>%1: group: '%2' is not a non-negative integer</source>
            <translation>%1 : group : « %2 » n'est pas un entier positif ou nul</translation>
        </message>
        <message>
            <source>%1: motor: '%2' is not 0, 1 or 2</source>
            <translation>%1 : motor : « %2 » n'est pas 0, 1 ou 2</translation>
        </message>
        <message>
            <source>%1: a backlash mark needs a group and a motor, a grid mark neither</source>
            <translation>%1 : une marque de jeu a besoin d'un groupe et d'un moteur, une marque de grille d'aucun des deux</translation>
        </message>
        <message>
            <source>%1: ring_radius_mm: '%2' is not a positive number</source>
            <translation>%1 : ring_radius_mm : « %2 » n'est pas un nombre positif</translation>
        </message>
        <message>
            <source>%1: no marks</source>
            <translation>%1 : aucune marque</translation>
        </message>
        <message>
            <source>%1: backlash row %2 has %3 marks, expected 3</source>
            <translation>%1 : la rangée de jeu %2 a %3 marques, 3 attendues</translation>
        </message>
        <message>
            <source>%1: the file is empty (expected a header line: %2)</source>
            <translation>%1 : le fichier est vide (ligne d'en-tête attendue : %2)</translation>
        </message>
        <message>
            <source>%1: the header has no column %2 (expected %3)</source>
            <translation>%1 : l'en-tête n'a pas de colonne %2 (attendu : %3)</translation>
        </message>
        <message>
            <source>%1: missing field %2</source>
            <translation>%1 : champ %2 manquant</translation>
        </message>
        <message>
            <source>%1: %2 is not a number: "%3"</source>
            <translation>%1 : %2 n'est pas un nombre : « %3 »</translation>
        </message>
        <message>
            <source>%1: duplicate mark id %2 (first on line %3)</source>
            <translation>%1 : identifiant de marque %2 en double (d'abord à la ligne %3)</translation>
        </message>
        <message>
            <source>%1: a distance from mark %2 to itself</source>
            <translation>%1 : une distance de la marque %2 à elle-même</translation>
        </message>
        <message>
            <source>%1: distance_mm must be positive</source>
            <translation>%1 : distance_mm doit être positive</translation>
        </message>
        <message>
            <source>%1: duplicate distance %2-%3 (first on line %4)</source>
            <translation>%1 : distance %2-%3 en double (d'abord à la ligne %4)</translation>
        </message>
        <message>
            <source>cannot open %1: %2</source>
            <translation>impossible d'ouvrir %1 : %2</translation>
        </message>
    </context>
    <context>
        <name>CalibrationFit</name>
        <message>
            <source>the measurements do not depend on %1 at all</source>
            <translation>les mesures ne dépendent pas du tout de %1</translation>
        </message>
        <message>
            <source>the fit is ill-conditioned (condition number %1 &gt; %2): the marks cannot separate %3; spread the marks over the whole working area</source>
            <translation>l'ajustement est mal conditionné (conditionnement %1 &gt; %2) : les repères ne permettent pas de séparer %3 ; répartissez les repères sur toute la zone de travail</translation>
        </message>
        <message>
            <source>%1 distances are too few for %2 parameters: at least %3 distances are needed</source>
            <translation>%1 distances sont trop peu pour %2 paramètres : il faut au moins %3 distances</translation>
        </message>
        <message>
            <source>%1 marks are too few for %2 parameters: at least %3 marks are needed</source>
            <translation>%1 repères sont trop peu pour %2 paramètres : il faut au moins %3 repères</translation>
        </message>
        <message>
            <source>a mark's commanded angles do not close the nominal machine's loop</source>
            <translation>les angles commandés d'un repère ne ferment pas la boucle de la machine nominale</translation>
        </message>
        <message>
            <source>the fit did not converge within %1 evaluations (are the commanded angles and measurements of the same marks?)</source>
            <translation>l'ajustement n'a pas convergé en %1 évaluations (les angles commandés et les mesures sont-ils ceux des mêmes repères ?)</translation>
        </message>
        <message>
            <source>the final fit did not converge within %1 evaluations</source>
            <translation>l'ajustement final n'a pas convergé en %1 évaluations</translation>
        </message>
        <message>
            <source>line %1: mark %2 is not in the marks file</source>
            <translation>ligne %1 : le repère %2 n'est pas dans le fichier des repères</translation>
        </message>
        <message>
            <source>only %1 grid marks measured: at least 3 are needed to place the sheet</source>
            <translation>seulement %1 marques de grille mesurées : il en faut au moins 3 pour placer la feuille</translation>
        </message>
        <message>
            <source>the measured grid marks all lie on one point</source>
            <translation>les marques de grille mesurées sont toutes au même point</translation>
        </message>
        <message>
            <source>no backlash row has all three marks measured</source>
            <translation>aucune rangée de jeu n'a ses trois marques mesurées</translation>
        </message>
    </context>
    <context>
        <name>CalibrationPattern</name>
        <message>
            <source>pattern options out of range</source>
            <translation>options du motif hors limites</translation>
        </message>
        <message>
            <source>no point of the working area (mode %1) has room for a mark</source>
            <translation>aucun point de la zone de travail (mode %1) n'a la place pour un repère</translation>
        </message>
        <message>
            <source>only %1 marks fit %2 mm apart in the working area; at least %3 are needed</source>
            <translation>seuls %1 repères tiennent à %2 mm d'écart dans la zone de travail ; il en faut au moins %3</translation>
        </message>
        <message>
            <source>no drawing order keeps every move between marks under half a turn of a motor</source>
            <translation>aucun ordre de tracé ne garde chaque déplacement entre repères sous un demi-tour de moteur</translation>
        </message>
        <message>
            <source>approach of mark %1</source>
            <translation>approche du repère %1</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1 : %2</translation>
        </message>
    </context>
    <context>
        <name>CalibrationScan</name>
        <message>
            <source>the pattern has fewer than 3 marks</source>
            <translation>le motif a moins de 3 repères</translation>
        </message>
        <message>
            <source>found %1 marks, the pattern has %2</source>
            <translation>%1 repères trouvés, le motif en a %2</translation>
        </message>
        <message>
            <source>no two found marks are as far apart as the pattern's marks (is the dpi right?)</source>
            <translation>aucun couple de repères trouvés n'est aussi écarté que les repères du motif (la résolution est-elle juste ?)</translation>
        </message>
        <message>
            <source>only %1 of the pattern's %2 marks match the found ones (%3 found): not this pattern, or the dpi is wrong</source>
            <translation>seuls %1 des %2 repères du motif correspondent à ceux trouvés (%3 trouvés) : ce n'est pas ce motif, ou la résolution est fausse</translation>
        </message>
        <message>
            <source>ambiguous: two placements of the sheet match %1 and %2 marks</source>
            <translation>ambigu : deux positions de la feuille correspondent à %1 et %2 repères</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1 : %2</translation>
        </message>
        <message>
            <source>the dpi must be a positive number</source>
            <translation>la résolution (dpi) doit être un nombre positif</translation>
        </message>
        <message>
            <source>the image is empty</source>
            <translation>l'image est vide</translation>
        </message>
        <message>
            <source>the pattern has no marks</source>
            <translation>le motif n'a aucun repère</translation>
        </message>
        <message>
            <source>no ink found (the image has almost no contrast)</source>
            <translation>aucune encre trouvée (l'image n'a presque pas de contraste)</translation>
        </message>
        <message>
            <source>no marks found at %1 dpi: the pattern's rings are %2 mm across (%3 px); the ring-like shapes in the image are about %4 px: is it scanned at about %5 dpi?</source>
            <translation>aucun repère trouvé à %1 dpi : les anneaux du motif font %2 mm de diamètre (%3 px) ; les formes en anneau de l'image font environ %4 px : est-elle numérisée à environ %5 dpi ?</translation>
        </message>
        <message>
            <source>no marks found at %1 dpi: the pattern's rings are %2 mm across (%3 px)</source>
            <translation>aucun repère trouvé à %1 dpi : les anneaux du motif font %2 mm de diamètre (%3 px)</translation>
        </message>
        <message>
            <source>cannot read the image (%1)</source>
            <translation>impossible de lire l'image (%1)</translation>
        </message>
        <message>
            <source>found %1 parallel lines of about %2 mm at %3 dpi, expected %4 (is the dpi right, and the whole pattern on the scan?)</source>
            <translation>%1 lignes parallèles d'environ %2 mm trouvées à %3 dpi, %4 attendues (la résolution est-elle juste, et tout le motif est-il sur la numérisation ?)</translation>
        </message>
        <message>
            <source>the line near (%1, %2) mm has no clear ends</source>
            <translation>la ligne près de (%1, %2) mm n'a pas d'extrémités nettes</translation>
        </message>
    </context>
    <context>
        <name>Jog</name>
        <message>
            <source>the machine position is not known yet</source>
            <translation>la position de la machine n'est pas encore connue</translation>
        </message>
        <message>
            <source>the current motor angles do not close the linkage</source>
            <translation>les angles actuels des moteurs ne ferment pas la liaison</translation>
        </message>
        <message>
            <source>the line leaves the workspace</source>
            <translation>la ligne sort de l'espace de travail</translation>
        </message>
        <message>
            <source>the arms cannot follow the straight line closely enough</source>
            <translation>les bras ne peuvent pas suivre la ligne droite d'assez près</translation>
        </message>
        <message>
            <source>stopped after %1 mm: %2</source>
            <translation>arrêté après %1 mm : %2</translation>
        </message>
        <message>
            <source>no jog direction</source>
            <translation>aucune direction de déplacement</translation>
        </message>
        <message>
            <source>no safe travel to that point</source>
            <translation>aucun trajet sûr vers ce point</translation>
        </message>
        <message>
            <source>the point is out of reach</source>
            <translation>le point est hors de portée</translation>
        </message>
        <message>
            <source>the job has no pen-down strokes to frame</source>
            <translation>le travail n'a aucun trait stylo baissé à encadrer</translation>
        </message>
        <message>
            <source>cannot reach the frame's first corner: %1</source>
            <translation>impossible d'atteindre le premier coin du cadre : %1</translation>
        </message>
        <message>
            <source>frame edge %1: %2</source>
            <translation>côté du cadre %1 : %2</translation>
        </message>
    </context>
    <context>
        <name>MotionCheck</name>
        <message>
            <source>G2/G3 arcs are not arcs in joint space (X and Y are motor angles): plan the drawing with 'fivebar plan', which turns arcs into checked straight segments</source>
            <translation>les arcs G2/G3 ne sont pas des arcs dans l'espace articulaire (X et Y sont des angles moteur) : planifiez le dessin avec 'fivebar plan', qui transforme les arcs en segments droits vérifiés</translation>
        </message>
        <message>
            <source>probing (G38) is not supported on a five-bar machine</source>
            <translation>le palpage (G38) n'est pas pris en charge sur une machine à cinq barres</translation>
        </message>
        <message>
            <source>G20 (inches) would scale the motor angles by 25.4: X and Y are degrees, use G21</source>
            <translation>G20 (pouces) multiplierait les angles moteur par 25,4 : X et Y sont en degrés, utilisez G21</translation>
        </message>
        <message>
            <source>G10/G92 change the coordinates the checks rely on: %1</source>
            <translation>G10/G92 changent les coordonnées sur lesquelles reposent les vérifications : %1</translation>
        </message>
        <message>
            <source>G55-G59 select another work coordinate system; the checked link works in G54</source>
            <translation>G55-G59 choisissent un autre système de coordonnées de travail ; la liaison vérifiée travaille en G54</translation>
        </message>
        <message>
            <source>a jog ($J=) takes only G90, G91, G53 and G21</source>
            <translation>un déplacement manuel ($J=) n'accepte que G90, G91, G53 et G21</translation>
        </message>
        <message>
            <source>the board would refuse the jog (error:15)</source>
            <translation>la carte refuserait le déplacement (error:15)</translation>
        </message>
        <message>
            <source>the board would stop with a soft-limit alarm (ALARM:2)</source>
            <translation>la carte s'arrêterait avec une alarme de fin de course logicielle (ALARM:2)</translation>
        </message>
        <message>
            <source>the target %1 takes motor %2 to %3 deg in machine coordinates, outside the board's soft-limit travel %4..0 deg ($%5=%6): %7; home the machine or set its reference so that the travel matches the profile, or choose a target inside it</source>
            <translation>la cible %1 amène le moteur %2 à %3 degrés en coordonnées machine, hors de la course logicielle de la carte %4..0 degrés ($%5=%6) : %7 ; faites la prise d'origine ou définissez la référence de sorte que la course corresponde au profil, ou choisissez une cible à l'intérieur</translation>
        </message>
        <message>
            <source>set the machine's reference with 'fivebar reference' (or home it with 'fivebar home')</source>
            <translation>définissez la référence de la machine avec 'fivebar reference' (ou faites sa prise d'origine avec 'fivebar home')</translation>
        </message>
        <message>
            <source>choose a target inside the workspace (fivebar workspace shows it)</source>
            <translation>choisissez une cible dans l'espace de travail ('fivebar workspace' le montre)</translation>
        </message>
        <message>
            <source>(%1, %2) deg</source>
            <translation>(%1, %2) degrés</translation>
        </message>
        <message>
            <source>G28/G30 go to a position stored on the board, which is not known here; move to the point with a G0 line instead</source>
            <translation>G28/G30 vont à une position enregistrée sur la carte, inconnue ici ; allez au point avec une ligne G0 à la place</translation>
        </message>
        <message>
            <source>the machine's position %1 is not a safe pose of %2 (%3), so no move from it can be checked: %4 first</source>
            <translation>la position de la machine %1 n'est pas une pose sûre de %2 (%3), donc aucun mouvement depuis elle ne peut être vérifié : %4 d'abord</translation>
        </message>
        <message>
            <source>the move from %1 to %2 %3; %4</source>
            <translation>le mouvement de %1 à %2 %3 ; %4</translation>
        </message>
    </context>
    <context>
        <name>SoftLimits</name>
        <message>
            <source>line %1 moves motor %2 to %3 deg in machine coordinates, outside the board's soft-limit travel %4..0 ($%5=%6)</source>
            <translation>la ligne %1 amène le moteur %2 à %3 degrés en coordonnées machine, hors de la course logicielle de la carte %4..0 ($%5=%6)</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::BoardPreflight</name>
        <message>
            <source>The board's soft limits would stop this job with an alarm (ALARM:2): %1. The board checks its travel ($130, $131) in machine coordinates, which the reference pose shifted against the drawing's. Home the machine, or make the board's settings match the profile (Machine settings...), then start again.</source>
            <translation>Les fins de course logicielles de la carte arrêteraient ce travail avec une alarme (ALARM:2) : %1. La carte vérifie sa course ($130, $131) en coordonnées machine, que la pose de référence a décalées par rapport à celles du dessin. Faites la prise d'origine de la machine, ou alignez les réglages de la carte sur le profil (Réglages de la machine...), puis relancez.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachineLayer</name>
        <message>
            <source>Position unknown: set the reference pose</source>
            <translation>Position inconnue : définissez la pose de référence</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::PortBox</name>
        <message>
            <source>/dev/ttyUSB0 or tcp:HOST:PORT</source>
            <translation>/dev/ttyUSB0 ou tcp:HOST:PORT</translation>
        </message>
        <message>
            <source>The board's port: pick one, or type any name: a serial device, a /dev/serial/by-id link, a pseudo-terminal (e.g. the firmware simulator's) or a network port tcp:HOST:PORT (ser2net, a FluidNC or grblHAL board)</source>
            <translation>Le port de la carte : choisissez-en un ou tapez n'importe quel nom : un périphérique série, un lien /dev/serial/by-id, un pseudo-terminal (p. ex. celui du simulateur de firmware) ou un port réseau tcp:HOST:PORT (ser2net, une carte FluidNC ou grblHAL)</translation>
        </message>
        <message>
            <source>Simulated machine (built in)</source>
            <translation>Machine simulée (intégrée)</translation>
        </message>
        <message>
            <source>Connected to recently</source>
            <translation>Connecté récemment</translation>
        </message>
        <message>
            <source>Choose a port or type its name, for example /dev/ttyUSB0, a pseudo-terminal such as /tmp/grblpty, or a network port tcp:HOST:PORT.</source>
            <translation>Choisissez un port ou tapez son nom, par exemple /dev/ttyUSB0, un pseudo-terminal comme /tmp/grblpty ou un port réseau tcp:HOST:PORT.</translation>
        </message>
        <message>
            <source>%1 is not a network port: write it as tcp:HOST:PORT, for example tcp:192.168.1.20:23.</source>
            <translation>%1 n'est pas un port réseau : écrivez-le sous la forme tcp:HOST:PORT, par exemple tcp:192.168.1.20:23.</translation>
        </message>
        <message>
            <source>There is no port %1. Check the name, that the board is plugged in and powered, or that the simulator is running (Refresh lists the serial ports found).</source>
            <translation>Il n'y a pas de port %1. Vérifiez le nom, que la carte est branchée et alimentée, ou que le simulateur tourne (Actualiser liste les ports série trouvés).</translation>
        </message>
        <message>
            <source>%1 is a folder, not a port: choose the board's serial port (e.g. /dev/ttyUSB0) or type a network port tcp:HOST:PORT.</source>
            <translation>%1 est un dossier, pas un port : choisissez le port série de la carte (p. ex. /dev/ttyUSB0) ou tapez un port réseau tcp:HOST:PORT.</translation>
        </message>
        <message>
            <source>%1 is a file, not a port: choose the board's serial port (e.g. /dev/ttyUSB0) or type a network port tcp:HOST:PORT.</source>
            <translation>%1 est un fichier, pas un port : choisissez le port série de la carte (p. ex. /dev/ttyUSB0) ou tapez un port réseau tcp:HOST:PORT.</translation>
        </message>
        <message>
            <source>No permission to use %1: add your user to the group that owns it (usually dialout: sudo adduser $USER dialout), then log out and in again.</source>
            <translation>Pas d'autorisation pour utiliser %1 : ajoutez votre utilisateur au groupe qui le possède (en général dialout : sudo adduser $USER dialout), puis déconnectez-vous et reconnectez-vous.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::RecoveryBar</name>
        <message>
            <source>Reset</source>
            <translation>Réinitialiser</translation>
        </message>
        <message>
            <source>Soft reset (Ctrl-X): stops everything; the machine keeps its position unless it was moving.</source>
            <translation>Réinitialisation logicielle (Ctrl-X) : arrête tout ; la machine garde sa position sauf si elle bougeait.</translation>
        </message>
        <message>
            <source>Unlock ($X)</source>
            <translation>Déverrouiller ($X)</translation>
        </message>
        <message>
            <source>Leave the alarm state without homing. Only when you know the machine stands where the studio shows it.</source>
            <translation>Quitter l'état d'alarme sans prise d'origine. Seulement si vous savez que la machine est là où le studio l'affiche.</translation>
        </message>
        <message>
            <source>Alarm %1</source>
            <translation>Alarme %1</translation>
        </message>
        <message>
            <source>Home ($H)</source>
            <translation>Origine ($H)</translation>
        </message>
        <message>
            <source>Set reference pose</source>
            <translation>Définir la pose de référence</translation>
        </message>
        <message>
            <source>Run the homing cycle; the machine moves to its switches.</source>
            <translation>Lancer la prise d'origine ; la machine va jusqu'à ses capteurs.</translation>
        </message>
        <message>
            <source>Declare that the machine now stands at the profile's home pose (G10 L20).</source>
            <translation>Déclarer que la machine est maintenant dans la pose d'origine du profil (G10 L20).</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::AlarmStrip</name>
        <message>
            <source>Alarm %1: the machine stopped.</source>
            <translation>Alarme %1 : la machine s'est arrêtée.</translation>
        </message>
        <message>
            <source>Alarm: the machine is locked.</source>
            <translation>Alarme : la machine est verrouillée.</translation>
        </message>
        <message>
            <source>Reset, Unlock and Set reference pose are in the status bar and the Machine panel.</source>
            <translation>Réinitialiser, Déverrouiller et Définir la pose de référence se trouvent dans la barre d'état et le panneau Machine.</translation>
        </message>
    </context>
    <context>
        <name>GrblSetting</name>
        <message>
            <source>Step pulse time</source>
            <translation>Durée d’impulsion de pas</translation>
        </message>
        <message>
            <source>Step idle delay (255: motors always on)</source>
            <translation>Délai avant repos des moteurs (255 : toujours alimentés)</translation>
        </message>
        <message>
            <source>Step pulse invert (bit mask)</source>
            <translation>Inversion des impulsions de pas (masque de bits)</translation>
        </message>
        <message>
            <source>Direction invert (bit mask)</source>
            <translation>Inversion de direction (masque de bits)</translation>
        </message>
        <message>
            <source>Invert step enable pin (on/off)</source>
            <translation>Inverser la broche d’activation (oui/non)</translation>
        </message>
        <message>
            <source>Invert limit pins (on/off)</source>
            <translation>Inverser les broches de fin de course (oui/non)</translation>
        </message>
        <message>
            <source>Invert probe pin (on/off)</source>
            <translation>Inverser la broche de palpeur (oui/non)</translation>
        </message>
        <message>
            <source>Status report options (bit mask)</source>
            <translation>Options du rapport d’état (masque de bits)</translation>
        </message>
        <message>
            <source>Junction deviation</source>
            <translation>Déviation de jonction</translation>
        </message>
        <message>
            <source>Arc tolerance</source>
            <translation>Tolérance des arcs</translation>
        </message>
        <message>
            <source>Report in inches (on/off)</source>
            <translation>Rapport en pouces (oui/non)</translation>
        </message>
        <message>
            <source>Soft limits (on/off)</source>
            <translation>Limites logicielles (oui/non)</translation>
        </message>
        <message>
            <source>Hard limits (on/off)</source>
            <translation>Limites matérielles (oui/non)</translation>
        </message>
        <message>
            <source>Homing cycle (on/off)</source>
            <translation>Cycle de prise d’origine (oui/non)</translation>
        </message>
        <message>
            <source>Homing direction invert (bit mask)</source>
            <translation>Inversion du sens de prise d’origine (masque de bits)</translation>
        </message>
        <message>
            <source>Homing locate feed rate</source>
            <translation>Prise d’origine : vitesse de localisation</translation>
        </message>
        <message>
            <source>Homing search seek rate</source>
            <translation>Prise d’origine : vitesse de recherche</translation>
        </message>
        <message>
            <source>Homing switch debounce delay</source>
            <translation>Prise d’origine : anti-rebond des contacts</translation>
        </message>
        <message>
            <source>Homing switch pull-off distance</source>
            <translation>Prise d’origine : distance de dégagement</translation>
        </message>
        <message>
            <source>Maximum spindle speed (largest S value)</source>
            <translation>Vitesse de broche maximale (plus grande valeur S)</translation>
        </message>
        <message>
            <source>Minimum spindle speed (smallest S value)</source>
            <translation>Vitesse de broche minimale (plus petite valeur S)</translation>
        </message>
        <message>
            <source>Laser mode (on/off)</source>
            <translation>Mode laser (oui/non)</translation>
        </message>
        <message>
            <source>Motor 1 (X) steps per degree</source>
            <translation>Moteur 1 (X) : pas par degré</translation>
        </message>
        <message>
            <source>Motor 2 (Y) steps per degree</source>
            <translation>Moteur 2 (Y) : pas par degré</translation>
        </message>
        <message>
            <source>Z steps per mm</source>
            <translation>Z : pas par mm</translation>
        </message>
        <message>
            <source>Motor 1 (X) maximum rate</source>
            <translation>Moteur 1 (X) : vitesse maximale</translation>
        </message>
        <message>
            <source>Motor 2 (Y) maximum rate</source>
            <translation>Moteur 2 (Y) : vitesse maximale</translation>
        </message>
        <message>
            <source>Z maximum rate</source>
            <translation>Z : vitesse maximale</translation>
        </message>
        <message>
            <source>Motor 1 (X) acceleration</source>
            <translation>Moteur 1 (X) : accélération</translation>
        </message>
        <message>
            <source>Motor 2 (Y) acceleration</source>
            <translation>Moteur 2 (Y) : accélération</translation>
        </message>
        <message>
            <source>Z acceleration</source>
            <translation>Z : accélération</translation>
        </message>
        <message>
            <source>Motor 1 (X) maximum travel</source>
            <translation>Moteur 1 (X) : course maximale</translation>
        </message>
        <message>
            <source>Motor 2 (Y) maximum travel</source>
            <translation>Moteur 2 (Y) : course maximale</translation>
        </message>
        <message>
            <source>Z maximum travel</source>
            <translation>Z : course maximale</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::RunProgressBox</name>
        <message>
            <source>Stop</source>
            <translation>Arrêter</translation>
        </message>
        <message>
            <source>Stop cleanly: feed hold, then reset with the position kept and the pen up</source>
            <translation>Arrêter proprement : arrêt de l’avance, puis réinitialisation en gardant la position, stylo levé</translation>
        </message>
        <message>
            <source>%1 % (%2)</source>
            <translation>%1 % (%2)</translation>
        </message>
        <message>
            <source>%1 left</source>
            <translation>%1 restant</translation>
        </message>
    </context>
    <context>
        <name>fivebar::studio::HelpMenu</name>
        <message>
            <source>&amp;First job guide</source>
            <translation>Guide du &amp;premier travail</translation>
        </message>
        <message>
            <source>Connect, load a drawing, place it, preview and run: step by step</source>
            <translation>Connecter, charger un dessin, le placer, le prévisualiser et le lancer : pas à pas</translation>
        </message>
        <message>
            <source>&amp;Documentation</source>
            <translation>&amp;Documentation</translation>
        </message>
        <message>
            <source>Documentation</source>
            <translation>Documentation</translation>
        </message>
        <message>
            <source>The documentation file %1 is not installed. It is also on the project's pages, in the docs folder.</source>
            <translation>Le fichier de documentation %1 n’est pas installé. Il se trouve aussi sur les pages du projet, dans le dossier docs.</translation>
        </message>
    </context>
</TS>
