<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>
<qgis version="3.28.0" styleCategories="Symbology">
  <pipe>
    <rasterrenderer type="singlebandpseudocolor" band="1" opacity="1">
      <rastershader>
        <colorrampshader colorRampType="EXACT" classificationMode="1">
          <item value="10" label="Tree cover" color="#006400" alpha="255"/>
          <item value="20" label="Shrubland" color="#ffbb22" alpha="255"/>
          <item value="80" label="Permanent water bodies" color="#0064c8" alpha="255"/>
        </colorrampshader>
      </rastershader>
    </rasterrenderer>
  </pipe>
</qgis>
