<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR">
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
        <translation>Sa planification et son tracé peuvent être très longs. L&apos;importer quand même ?</translation>
    </message>
</context>
<context>
    <name>JobPipeline</name>
    <message>
        <source>Nothing to plan: the drawing has no visible path.</source>
        <translation>Rien à planifier : le dessin n&apos;a aucun tracé visible.</translation>
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
    <name>QObject</name>
    <message>
        <source>Planning failed: %1</source>
        <translation>Échec de la planification : %1</translation>
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
        <translation>limite d&apos;atteinte</translation>
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
        <translation>%1 contient des modifications non enregistrées. Les enregistrer d&apos;abord ?</translation>
    </message>
    <message>
        <source>Cannot save %1: %2</source>
        <translation>Impossible d&apos;enregistrer %1 : %2</translation>
    </message>
    <message>
        <source>Nothing to save: open a drawing first.</source>
        <translation>Rien à enregistrer : ouvrez d&apos;abord un dessin.</translation>
    </message>
    <message>
        <source>Save failed</source>
        <translation>Échec de l&apos;enregistrement</translation>
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
        <translation>Il n&apos;y a aucune tâche planifiée à exporter (voir l&apos;aperçu de la tâche).</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Impossible d&apos;écrire %1 : %2</translation>
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
        <translation>La nouvelle langue s&apos;applique au prochain démarrage de FiveBar Studio.</translation>
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
        <translation>&amp;Ajuster le dessin à l&apos;espace de travail</translation>
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
        <translation>&lt;b&gt;FiveBar Studio %1&lt;/b&gt;&lt;p&gt;Planifie et simule des dessins pour robots à cinq barres : analyse de l&apos;espace de travail et des singularités, planification sûre des tâches, sortie GRBL.&lt;/p&gt;</translation>
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
        <translation>Avertissements d&apos;import</translation>
    </message>
</context>
<context>
    <name>fivebar::widgets::ConsolePanel</name>
    <message>
        <source>Lines sent to and received from the machine appear here.</source>
        <translation>Les lignes envoyées à la machine et reçues d&apos;elle apparaissent ici.</translation>
    </message>
    <message>
        <source>G-code or $ command, e.g. $$ or G0 X10 Y20</source>
        <translation>G-code ou commande $, p. ex. $$ ou G0 X10 Y20</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Envoyer</translation>
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
        <source>Outline: the shape&apos;s edge (as AxiDraw and vpype draw fills). Hatch: parallel lines inside the shape. Not drawn: fill-only shapes are left out.</source>
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
        <translation>Connectez d&apos;abord la machine : sa position est inconnue.</translation>
    </message>
    <message>
        <source>Go to %1, %2 mm? The dashed path is the pen&apos;s travel (%3 checked moves).</source>
        <translation>Aller à %1, %2 mm ? Le tracé en pointillés est le trajet du stylo (%3 mouvements vérifiés).</translation>
    </message>
    <message>
        <source>Cannot go there: %1</source>
        <translation>Impossible d&apos;y aller : %1</translation>
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
        <translation>%1 n&apos;a pas pu être importé.</translation>
    </message>
    <message>
        <source>Import failed</source>
        <translation>Échec de l&apos;import</translation>
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
</context>
<context>
    <name>fivebar::widgets::ImportWarningsPanel</name>
    <message>
        <source>No drawing imported yet.</source>
        <translation>Aucun dessin importé pour l&apos;instant.</translation>
    </message>
    <message>
        <source>What the importer dropped, approximated or could not draw. docs/svg-import.md lists what is supported.</source>
        <translation>Ce que l&apos;import a omis, approché ou n&apos;a pas pu tracer. docs/svg-import.md liste ce qui est pris en charge.</translation>
    </message>
    <message>
        <source>%1 imported without warnings.</source>
        <translation>%1 importé sans avertissement.</translation>
    </message>
    <message>
        <source>1 warning while importing %1: part of the drawing may differ from what a browser shows.</source>
        <translation>1 avertissement à l&apos;import de %1 : une partie du dessin peut différer de ce qu&apos;affiche un navigateur.</translation>
    </message>
    <message>
        <source>%1 warnings while importing %2: parts of the drawing may differ from what a browser shows.</source>
        <translation>%1 avertissements à l&apos;import de %2 : des parties du dessin peuvent différer de ce qu&apos;affiche un navigateur.</translation>
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
    <name>fivebar::widgets::JogController</name>
    <message>
        <source>Jog refused: the machine is not connected, not idle, or a job is running.</source>
        <translation>Déplacement refusé : la machine n&apos;est pas connectée, pas au repos, ou une tâche est en cours.</translation>
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
        <translation>Tourner le moteur %1 d&apos;un pas dans le sens horaire</translation>
    </message>
    <message>
        <source>Turn motor %1 counter-clockwise by one step</source>
        <translation>Tourner le moteur %1 d&apos;un pas dans le sens antihoraire</translation>
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
        <translation>Lancer la prise d&apos;origine</translation>
    </message>
    <message>
        <source>Declare that the machine now stands at the profile&apos;s home pose</source>
        <translation>Déclarer que la machine est maintenant dans la pose d&apos;origine du profil</translation>
    </message>
    <message>
        <source>Speed of XY jogs</source>
        <translation>Vitesse des déplacements XY</translation>
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
        <translation>Réglages d&apos;outil du calque sélectionné</translation>
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
        <translation>Quitter l&apos;état d&apos;alarme sans prise d&apos;origine. Seulement si vous savez que la machine est là où le studio l&apos;affiche.</translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation>Fermer</translation>
    </message>
    <message>
        <source>Alarm %1: the machine stopped</source>
        <translation>Alarme %1 : la machine s&apos;est arrêtée</translation>
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
        <translation>La carte attend d&apos;abord une réinitialisation : appuyez sur Réinitialiser, puis Déverrouiller.</translation>
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
        <translation>Lancer la prise d&apos;origine ; la machine va jusqu&apos;à ses capteurs.</translation>
    </message>
    <message>
        <source>Declare that the machine now stands at the profile&apos;s home pose (G10 L20).</source>
        <translation>Déclarer que la machine est maintenant dans la pose d&apos;origine du profil (G10 L20).</translation>
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
        <translation>Prise d&apos;origine</translation>
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
</context>
<context>
    <name>fivebar::widgets::MachineSession</name>
    <message>
        <source>Cannot open %1.</source>
        <translation>Impossible d&apos;ouvrir %1.</translation>
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
        <translation>Non connecté : %1 n&apos;a pas été envoyé.</translation>
    </message>
    <message>
        <source>Not sent (%1): %2</source>
        <translation>Non envoyé (%1) : %2</translation>
    </message>
    <message>
        <source>A job is running: %1 was not sent.</source>
        <translation>Une tâche est en cours : %1 n&apos;a pas été envoyé.</translation>
    </message>
    <message>
        <source>Jog refused: the machine is not idle, not connected or a job is running.</source>
        <translation>Déplacement refusé : la machine n&apos;est pas au repos, pas connectée, ou une tâche est en cours.</translation>
    </message>
    <message>
        <source>%1 (jog in %2 checked moves)</source>
        <translation>%1 (déplacement en %2 mouvements vérifiés)</translation>
    </message>
    <message>
        <source>[soft reset]</source>
        <translation>[réinitialisation logicielle]</translation>
    </message>
    <message>
        <source>[feed hold]</source>
        <translation>[pause d&apos;avance]</translation>
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
        <translation>La machine est verrouillée (état d&apos;alarme). Déverrouillez-la avec $X ou faites sa prise d&apos;origine avec $H une fois que vous savez où elle se trouve.</translation>
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
</context>
<context>
    <name>fivebar::widgets::MachineSettingsDialog</name>
    <message>
        <source>Machine settings</source>
        <translation>Réglages de la machine</translation>
    </message>
    <message>
        <source>The board&apos;s GRBL settings next to the values the machine profile needs. Writing saves a backup of the board&apos;s settings first.</source>
        <translation>Les réglages GRBL de la carte à côté des valeurs dont le profil de machine a besoin. L&apos;écriture sauvegarde d&apos;abord les réglages de la carte.</translation>
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
        <translation>Connectez d&apos;abord la machine.</translation>
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
        <source>Reading the board&apos;s settings...</source>
        <translation>Lecture des réglages de la carte…</translation>
    </message>
    <message>
        <source>Nothing to write: read the board&apos;s settings first.</source>
        <translation>Rien à écrire : lisez d&apos;abord les réglages de la carte.</translation>
    </message>
    <message>
        <source>Write settings</source>
        <translation>Écrire les réglages</translation>
    </message>
    <message numerus="yes">
        <source>Write %n setting(s) to the board? Its current settings are saved to a backup file first.</source>
        <translation>
            <numerusform>Écrire %n réglage sur la carte ? Ses réglages actuels sont d&apos;abord sauvegardés dans un fichier.</numerusform>
            <numerusform>Écrire %n réglages sur la carte ? Ses réglages actuels sont d&apos;abord sauvegardés dans un fichier.</numerusform>
        </translation>
    </message>
    <message>
        <source>The board&apos;s settings match the profile.</source>
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
</context>
<context>
    <name>fivebar::widgets::MachineUi</name>
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
        <translation>Légende de l&apos;espace de travail</translation>
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
        <translation>Ajuster à l&apos;espace</translation>
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
        <translation>Mettre le dessin à l&apos;échelle du plus grand rectangle sans singularité</translation>
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
        <translation>Connexion et pose d&apos;origine</translation>
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
        <source>Limit the motor angles</source>
        <translation>Limiter les angles des moteurs</translation>
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
        <source> °/min</source>
        <translation> °/min</translation>
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
        <source> °/s²</source>
        <translation> °/s²</translation>
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
        <source> mm/min</source>
        <translation> mm/min</translation>
    </message>
    <message>
        <source>Laser power S value</source>
        <translation>Valeur S de puissance laser</translation>
    </message>
    <message>
        <source>Working mode (built)</source>
        <translation>Mode de travail (montage)</translation>
    </message>
    <message>
        <source>Assembly mode</source>
        <translation>Mode d&apos;assemblage</translation>
    </message>
    <message>
        <source>Drawing speed</source>
        <translation>Vitesse de tracé</translation>
    </message>
    <message>
        <source> mm/s</source>
        <translation> mm/s</translation>
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
        <source>The machine has homing switches ($H)</source>
        <translation>La machine a des capteurs d&apos;origine ($H)</translation>
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
        <source>The profile is not applied until these problems are fixed.</source>
        <translation>Le profil n&apos;est pas appliqué tant que ces problèmes ne sont pas corrigés.</translation>
    </message>
    <message>
        <source>%1 cannot be used:
%2</source>
        <translation>%1 ne peut pas être utilisé :
%2</translation>
    </message>
    <message>
        <source>Fix the profile&apos;s problems before exporting it.</source>
        <translation>Corrigez les problèmes du profil avant de l&apos;exporter.</translation>
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
        <translation>Échec de l&apos;import</translation>
    </message>
    <message>
        <source>Export machine profile</source>
        <translation>Exporter le profil de machine</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Échec de l&apos;export</translation>
    </message>
</context>
<context>
    <name>fivebar::widgets::RunController</name>
    <message>
        <source>The connection was closed during the run. The progress is saved beside the job: reconnect and resume.</source>
        <translation>La connexion a été fermée pendant l&apos;exécution. La progression est enregistrée à côté de la tâche : reconnectez et reprenez.</translation>
    </message>
    <message>
        <source>Cannot start: connect the machine, wait until it is idle, and let the job plan first.</source>
        <translation>Impossible de démarrer : connectez la machine, attendez qu&apos;elle soit au repos et laissez d&apos;abord la tâche se planifier.</translation>
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
        <source>Resuming %1…</source>
        <translation>Reprise de %1…</translation>
    </message>
    <message>
        <source>Running %1…</source>
        <translation>Exécution de %1…</translation>
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
        <translation>En pause à cause d&apos;un problème</translation>
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
        <translation>Écrire la tâche planifiée en G-code et l&apos;envoyer à la machine</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Feed hold: the machine decelerates and waits</source>
        <translation>Pause d&apos;avance : la machine ralentit et attend</translation>
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
        <source>An interrupted run was saved (line %1 of %2 done): %3</source>
        <translation>Une exécution interrompue a été enregistrée (ligne %1 sur %2 faite) : %3</translation>
    </message>
    <message>
        <source>No job sent yet</source>
        <translation>Aucune tâche envoyée</translation>
    </message>
    <message>
        <source>%1 of %2 lines executed</source>
        <translation>%1 lignes exécutées sur %2</translation>
    </message>
    <message>
        <source>%1 left</source>
        <translation>reste %1</translation>
    </message>
    <message>
        <source>Long job</source>
        <translation>Tâche longue</translation>
    </message>
</context>
<context>
    <name>fivebar::widgets::SimulationPanel</name>
    <message>
        <source>Step back one move</source>
        <translation>Reculer d&apos;un mouvement</translation>
    </message>
    <message>
        <source>Play / pause the simulation</source>
        <translation>Lire / mettre en pause la simulation</translation>
    </message>
    <message>
        <source>Step forward one move</source>
        <translation>Avancer d&apos;un mouvement</translation>
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
        <translation>Changer les réglages d&apos;outil du calque</translation>
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
        <translation>Avec --screenshot : afficher la légende de l&apos;espace de travail (legend) ou une carte (transmission, conditioning ou resolution).</translation>
    </message>
    <message>
        <source>With --screenshot: simulation position as a fraction of the job (0 to 1).</source>
        <translation>Avec --screenshot : position de la simulation en fraction de la tâche (0 à 1).</translation>
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
        <source>User interface language: de, en, es or fr (default: View &gt; Language, else the system&apos;s).</source>
        <translation>Langue de l&apos;interface : de, en, es ou fr (par défaut : Affichage &gt; Langue, sinon celle du système).</translation>
    </message>
</context>
</TS>
